// Page wiring: one worker owns the core; the page sends scenarios and draws what comes back.
import { Plots, PLOTS, png } from './plots.js';
import { composeScenario, fieldControl, fieldValue, forwardKnob, markInvalid, renderFields } from './controls.js';
import { DEFAULT_SCENARIO, decodePins, excerpt, fragment, markRun, presetNamed, scenarioFromUrl, setFragment, showScenario } from './url.js';
import { Analysis, formatSweep, isCount, parseSweep } from './analysis.js';
import uPlot from '../vendor/uPlot.esm.js';
import { Walkthrough } from './walkthrough.js';
import { LessonPanel } from './lessons.js';
import { LESSONS } from './teaching.js';

const $ = (id) => document.getElementById(id);
const ui = {
  preset: $('preset'), presetDoc: $('preset-doc'), form: $('settings'), run: $('run'),
  cancel: $('cancel'), progress: $('progress'), status: $('status'), message: $('message'),
  copy: $('copy-link'), csv: $('export-csv'), png: $('export-png'), plots: $('plots'),
  present: $('present'), inspect: $('inspect'), settingsToggle: $('settings-toggle'), embed: $('copy-embed'), fullRun: $('full-run'), fit: $('fit'), fitLabel: $('fit-label'),
  unrun: $('unrun'), figures: $('figures'), consistency: $('consistency'), keyFigures: $('key-figures'), figuresBar: document.querySelector('.figures-bar'), figuresToggle: $('figures-toggle'),
};

const state = {
  info: null, // the core's description of the scenario in the form
  presets: [],
  nisBand: [0, 0],
  pins: [], // pinned scenarios, in pin order
  shared: { pins: fragment('pins'), sweep: fragment('sweep') }, // from the link that opened the page
  notice: null, // a notice about the link that stays until the user acts
  pinning: false, // pins are being run in the worker
  runId: 0,
  running: false,
  ranScenario: null, // the scenario of the last run started
  workerReady: false, // whether the current worker has loaded the core
  started: 0,
  req: 0,
  pending: new Map(), // describe requests: req → {resolve, reject}
  transient: null, // {t, reason}: the end of the start-up transient, from the core
  figures: [], // the run's figures, from the core
  knobIds: new Map(), // walkthrough knobs given out per field, for unique ids
  presetPending: false, // the picker moved by keyboard, not yet committed
  export: null, // the CSV export under way: {serial, parts: [Blob]}
  exportSerial: 0,
  walkthroughAsked: 0, // the run whose whole-run walkthrough view was asked for
  shownRun: 0, // the run the plots show
};

/**
 * Resolves once the browser has rendered the next frame (at once for a hidden page, and after a
 * second at most).
 */
const painted = () => new Promise((resolve) => {
  if (document.hidden) {
    resolve(); // a hidden page paints nothing
    return;
  }
  requestAnimationFrame(() => setTimeout(resolve, 0));
  setTimeout(resolve, 1000);
});

/** Whether the y-axes leave out the start-up transient, and from which time. */
const framing = () => ({ fit: ui.fit.checked && state.transient !== null, from: state.transient?.t ?? -Infinity });
const ifocRun = () => fieldValue(state.info, 'controller') === 'ifoc';

const PLOT_HEIGHT = { normal: [260, 220], present: [380, 320] };
// The least height of an embedded plot, however small its frame (px).
const EMBED_MIN_HEIGHT = 120;
const EMBED_MARGIN = 8;
// Presentation mode draws plot text and lines this much larger: 14 px ticks become 21 px.
const PRESENT_SCALE = 1.5;
const sampleTime = () => Number(fieldValue(state.info, 'ts')) || null;
const plots = new Plots(ui.plots, PLOTS, {
  onWindow: (t0, t1) => requestWindow(t0, t1),
  onFull: () => fullRun(),
  onPick: (t) => requestInspect(t),
  sampleTime,
  framing,
  constants: (plot) => (plot.constants ? [1, -1].map((s) => s * componentLimit()) : []),
});
const walkthrough = new Walkthrough({
  container: $('walkthrough'),
  inspectBox: ui.inspect,
  // A field can be a knob in several sections: the first is `knob-KEY`, later ones
  // `knob-KEY-2`, ... (ids stay unique; the ids given out are counted per description).
  knob: (key) => {
    const f = state.info?.fields.find((x) => x.key === key && x.value !== null && x.acts);
    if (!f) return null;
    const n = (state.knobIds.get(key) ?? 0) + 1;
    state.knobIds.set(key, n);
    return fieldControl(f, n === 1 ? 'knob' : `knob${n}`);
  },
  onCompare: () => {
    $('walkthrough').querySelector('.compare-result').textContent = 'Running both predictors…';
    worker.postMessage({ type: 'compare', id: state.runId });
  },
  onWindow: (t0, t1) => requestWindow(t0, t1),
  onFull: () => fullRun(),
  onPick: (t) => requestInspect(t),
  framing,
});
walkthrough.plots.sampleTime = sampleTime;
walkthrough.onInspect = (t) => {
  plots.mark(t);
  walkthrough.plots.mark(t);
};
const plotSets = [plots, walkthrough.plots];
const lessons = new LessonPanel({
  panel: $('lesson-panel'),
  list: $('lessons'),
  lessons: LESSONS,
  onOpen: async (lesson) => {
    // The lesson's own run brings the walkthrough's view; the last run's is not asked for.
    showTab(lesson.tab ?? 'plots', { fetch: false });
    window.scrollTo(0, 0);
    await load(lesson.run);
  },
});
const analysis = new Analysis({ scenario: () => state.info.encoded });
$('sweep-form').elements.namedItem('workers').value = analysis.pool.size;
let worker = null;

function say(text, kind = 'error') {
  ui.message.textContent = text;
  ui.message.className = text ? kind : '';
}

function setBusy(busy) {
  // Run is disabled while a run goes on, which drops its focus: give it back at the end, unless
  // the user has moved on to another control.
  const refocus = !busy && state.running && state.fromRun && [document.body, ui.run, null].includes(document.activeElement);
  state.running = busy;
  ui.run.disabled = busy || state.info === null;
  ui.cancel.disabled = !busy && state.export === null;
  // The worker holds one run: the one being computed, whose CSV is not whole yet.
  if (busy) ui.csv.disabled = true;
  document.body.dataset.state = busy ? 'running' : 'idle';
  if (refocus && !ui.run.disabled) ui.run.focus({ preventScroll: true });
}

function startWorker() {
  state.workerReady = false;
  worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
  worker.onmessage = ({ data }) => handlers[data.type](data);
  worker.onerror = (e) => {
    e.preventDefault();
    workerFailed(e.message || 'unknown error');
  };
  worker.onmessageerror = () => workerFailed('a message from it could not be read');
}

/**
 * The worker crashed (a trap in the core, or an uncaught error): it and everything it held (the
 * run, the pins) are gone. Ends what waited on it and starts a fresh one, unless it never
 * started, which a restart would only repeat.
 */
function workerFailed(reason) {
  worker.terminate();
  for (const { reject } of state.pending.values()) reject(new WorkerFailed(reason));
  state.pending.clear();
  if (state.export) endExport('failed', 'CSV export stopped');
  const wasRunning = state.running;
  state.pinning = false;
  setBusy(false);
  ui.csv.disabled = true;
  document.body.dataset.state = 'crashed';
  if (wasRunning) ui.status.textContent = 'Stopped: the simulation worker failed';
  if (!state.workerReady) {
    say(`The simulation worker could not start (${reason}). Reload the page to try again.`);
    return;
  }
  const dropped = state.pins.length ? ` The pinned runs were dropped: ${state.pins.map((p) => excerpt(p)).join('; ')}.` : '';
  say(`The simulation worker failed (${reason}). It was restarted; press Run to try again.${dropped}`);
  showPins([], []);
  startWorker();
}

/** A request the worker could not answer because it failed; the page has said so already. */
class WorkerFailed extends Error {}

/** Asks the core to validate and describe a scenario string ('recover' keeps its good fields). */
function describe(scenario, type = 'describe') {
  const req = ++state.req;
  return new Promise((resolve, reject) => {
    state.pending.set(req, { resolve, reject });
    worker.postMessage({ type, req, scenario });
  });
}

function applyDescription(info) {
  const shown = (i) => i?.fields.filter((f) => f.value !== null).map((f) => `${f.key}${f.acts ? '' : '-'}`).join();
  const keysBefore = shown(state.info);
  const keysAfter = shown(info);
  const presetChanged = ui.preset.value !== presetNamed(info.encoded);
  state.info = info;
  state.knobIds.clear();
  if (keysBefore !== keysAfter || presetChanged) renderFields(ui.form, info);
  else for (const f of info.fields) if (f.value !== null) syncControl(ui.form.elements.namedItem(f.key), f.value);
  walkthrough.describe(info);
  ui.preset.value = presetNamed(info.encoded);
  // The preset's description, and what this run changes of it (a lesson's run may hold another
  // speed or length than the preset says).
  const changed = info.encoded.split('&').slice(2).map((part) => part.split('=')[0]);
  const description = state.presets.find((p) => p.name === ui.preset.value)?.description ?? '';
  ui.presetDoc.textContent = changed.length ? `${description}. This run changes: ${changed.join(', ')}.` : description;
  ui.run.disabled = state.running;
  markInvalid(ui.form, null);
}

function syncControl(control, value) {
  if (!control || control === document.activeElement) return;
  if (control.type === 'checkbox') control.checked = value === '1';
  else control.value = value;
}

/** Loads a scenario string (from the URL, a preset or history); a bad one keeps its valid fields. */
async function load(text, { run = true } = {}) {
  let info;
  try {
    info = await describeLoaded(text);
  } catch (e) {
    if (e instanceof WorkerFailed) return;
    throw e;
  }
  applyDescription(info);
  showScenario(info.encoded);
  if (run) startRun();
}

/** The core's description of `text`, else of its valid fields, else of the default; says which. */
async function describeLoaded(text) {
  try {
    const info = await describe(text);
    say(state.notice ?? '', 'info');
    return info;
  } catch (e) {
    if (e instanceof WorkerFailed) throw e;
    try {
      // Keep what is valid; name every field that was left out.
      const info = await describe(text, 'recover');
      say(`Some settings in the address were rejected and left at the preset's values: ${listed(info.rejected, '; ')}.`);
      return info;
    } catch (again) {
      if (again instanceof WorkerFailed) throw again;
      say(`The scenario in the address was rejected: ${e.message}. Showing ${presetNamed(DEFAULT_SCENARIO)} instead.`);
      return describe(DEFAULT_SCENARIO);
    }
  }
}

/** Checks the form's scenario with the core; returns whether it is valid. An invalid value is
 * marked at its field, and at the walkthrough knob when a knob was edited. */
async function formChanged() {
  const text = composeScenario(ui.form, ui.preset.value);
  state.composed = text;
  try {
    const info = await describe(text);
    applyDescription(info);
    // The address keeps describing the run on screen until these settings run.
    markUnrun(info.encoded !== state.ranScenario);
    walkthrough.markKnob(null);
    say('');
    return true;
  } catch (e) {
    if (e instanceof WorkerFailed) return false;
    markUnrun(true);
    markInvalid(ui.form, e.message);
    // The field must be visible to be fixed: open the drawer where the settings live in one.
    if (ui.form.offsetParent === null && ui.form.querySelector('.invalid')) openSettings(true);
    const field = /field '([^']+)'/.exec(e.message)?.[1] ?? null;
    walkthrough.markKnob(field, e.message);
    ui.run.disabled = true;
    say(e.message);
    return false;
  }
}

/** A walkthrough knob was edited: check it and re-run, so its section's plots follow. */
async function knobChanged(knob) {
  clearTimeout(state.knobTimer);
  forwardKnob(ui.form, knob);
  if (await formChanged()) startRun();
}

/**
 * The first few `items` joined by `sep`, and how many more there are: a message quotes a bounded
 * number of parts of an address, however many it holds.
 */
function listed(items, sep = ', ') {
  const shown = items.slice(0, LISTED).join(sep);
  return items.length > LISTED ? `${shown} … and ${(items.length - LISTED).toLocaleString()} more` : shown;
}
const LISTED = 5;

// A pins fragment longer than this is refused whole (characters): four pins of the longest
// scenario the codec accepts (16 KiB each) fit.
const MAX_PINS_CHARS = 65_536;
// Pins sent to the worker from a link: one more than the core keeps, so that its refusal of the
// extra one is named.
const MAX_PINS_SENT = 5;

/** Marks the settings as changed and not yet run (or not), beside Run. */
function markUnrun(unrun) {
  ui.unrun.hidden = !unrun;
  if (unrun) document.body.dataset.unrun = '1';
  else delete document.body.dataset.unrun;
}

function startRun() {
  if (!state.info) return;
  markUnrun(false);
  // The first run is the link's own; a later one is the user's act, which ends the link's notice.
  if (state.runId > 0) state.notice = null;
  if (state.running) worker.postMessage({ type: 'cancel', id: state.runId });
  if (document.body.dataset.state === 'crashed') say(''); // the crash was told; this is the retry
  // The new run replaces the one being exported in the worker.
  if (state.export) {
    cancelExport('CSV export cancelled');
    say('The CSV export was cancelled: a new run started.', 'info');
  }
  const id = ++state.runId;
  state.ranScenario = state.info.encoded;
  markRun(state.info.encoded);
  state.fromRun = document.activeElement === ui.run; // started from Run: focus returns there
  document.body.dataset.scenario = state.info.encoded;
  document.body.dataset.started = id; // runs started: tests wait on it, not on a time
  state.started = performance.now();
  ui.progress.value = 0;
  ui.status.textContent = `Running ${state.info.steps.toLocaleString()} samples…`;
  walkthrough.closeInspect();
  setBusy(true);
  // The run keeps the whole-run view of the main plots, and of the walkthrough's once it has been
  // opened (until then they ask for theirs when it is, and a run does not pay for them).
  const groups = { ...plots.groups(), ...(walkthrough.opened ? walkthrough.plots.groups() : {}) };
  // With runs pinned, the run keeps the overlay's column as it goes.
  const overlay = state.pins.length ? $('overlay-column').value : null;
  worker.postMessage({ type: 'run', id, scenario: state.info.encoded, groups, buckets: buckets(), overlay });
}

// One bucket a pixel column of the widest plot.
const buckets = () => Math.max(200, Math.round(plots.width()));

/** Whether the worker holds the run the plots show (not a later one that was cancelled, refused or recorded nothing). */
const showingLastRun = () => !state.running && plots.full !== null && state.shownRun === state.runId;

function requestWindow(t0, t1) {
  if (!showingLastRun()) return;
  // uPlot reports each new chart's initial scale, the whole run, as a zoom; the charts already
  // hold the whole run, and for a run of a million rows each request would cost the worker seconds.
  if (t0 <= plots.full[0] && t1 >= plots.full[1]) return;
  for (const set of plotSets) set.window = [t0, t1];
  requestViews(t0, t1);
}

/** Returns every plot to the whole run. */
function fullRun() {
  if (!showingLastRun()) return;
  for (const set of plotSets) set.unzoom();
  requestViews(0, Number.MAX_VALUE);
}

/** Asks for a window of the main plots, and of the walkthrough's once they show this run. */
function requestViews(t0, t1) {
  requestView('plots', t0, t1);
  if (walkthrough.drawn()) requestView('walkthrough', t0, t1);
}

function requestView(set, t0, t1) {
  const groups = (set === 'walkthrough' ? walkthrough.plots : plots).groups();
  worker.postMessage({ type: 'view', id: state.runId, set, groups, t0, t1, buckets: buckets() });
}

/** Asks for the walkthrough's view of the whole run when it is on screen and does not have it yet. */
function walkthroughView() {
  if (!showingLastRun() || !walkthrough.stale || !walkthrough.visible()) return;
  if (state.walkthroughAsked === state.runId) return; // asked already
  state.walkthroughAsked = state.runId;
  requestView('walkthrough', 0, Number.MAX_VALUE);
}

function requestOverlay() {
  if (!state.pins.length) {
    $('overlay-plots').replaceChildren();
    return;
  }
  if (state.running || !plots.full) return;
  worker.postMessage({ type: 'overlay', id: state.runId, column: $('overlay-column').value, t0: 0, t1: Number.MAX_VALUE, buckets: Math.round(plots.width()) });
}

// Overlay of the current run and the pins, and their differences (all envelopes from the core).
function drawOverlay(column, data) {
  window.imlab.overlay = { column, data };
  const n = state.pins.length;
  const colors = ['#000', '#1f77b4', '#d62728', '#2ca02c', '#9467bd'];
  const label = $('overlay-column').selectedOptions[0].textContent;
  const chart = (title, names, series) => {
    const div = Object.assign(document.createElement('div'), { className: 'plot' });
    const opts = {
      title, width: plots.width(), height: 220, scales: { x: { time: false } },
      series: [{ label: 't (s)' }, ...names.map((name, i) => ({ label: name, stroke: colors[(i + (names[0] === 'current' ? 0 : 1)) % colors.length], width: 2 }))],
      axes: [{ label: 't (s)' }, { size: 80 }],
    };
    new uPlot(opts, [data[0], ...series], div);
    return div;
  };
  const pinNames = state.pins.map((_, i) => `pin ${i + 1}`);
  $('overlay-plots').replaceChildren(
    chart(`${label}: current run and pinned runs`, ['current', ...pinNames], data.slice(1, 2 + n)),
    chart(`${label}: current − pin`, pinNames.map((p) => `current − ${p}`), data.slice(2 + n)),
  );
}

function requestInspect(t) {
  if (!state.running && plots.full) worker.postMessage({ type: 'inspect', id: state.runId, t });
}

// The browser reads a blob: URL while it saves the download, which for a CSV of a gigabyte
// takes seconds; revoking the URL earlier would fail the download.
const REVOKE_AFTER_MS = 120_000;

function download(blob, name) {
  const a = Object.assign(document.createElement('a'), { href: URL.createObjectURL(blob), download: name });
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), REVOKE_AFTER_MS);
}

/** Asks the worker for the run's CSV, which arrives in chunks of rows (handlers.csv). */
function startExport() {
  const serial = ++state.exportSerial;
  state.export = { serial, parts: [] };
  ui.csv.disabled = true;
  ui.cancel.disabled = false;
  ui.progress.value = 0;
  ui.status.textContent = 'Exporting CSV…';
  document.body.dataset.export = 'running';
  worker.postMessage({ type: 'csv', id: state.runId, serial });
}

function cancelExport(status) {
  worker.postMessage({ type: 'csv-cancel', serial: state.export.serial });
  endExport('cancelled', status);
}

/** Ends the export under way: `outcome` is done, cancelled or failed, `status` the status line. */
function endExport(outcome, status) {
  state.export = null;
  ui.csv.disabled = false;
  ui.cancel.disabled = !state.running;
  ui.status.textContent = status;
  document.body.dataset.export = outcome;
}

function fileStem() {
  return `imlab-${presetNamed(state.info.encoded)}-${state.runId}`;
}

const TABS = [...document.querySelectorAll('[role=tab]')];

/** Shows tab `name`; with `fetch`, the walkthrough asks for the last run's view if it lacks it. */
function showTab(name, { fetch = true } = {}) {
  for (const tab of TABS) {
    const selected = tab.dataset.tab === name;
    tab.setAttribute('aria-selected', selected);
    tab.tabIndex = selected ? 0 : -1; // one tab stop for the tab list (WAI-ARIA tabs pattern)
    const panel = $(`panel-${tab.dataset.tab}`);
    panel.hidden = !selected;
    // The style keeps a hidden panel laid out (skipped, see style.css): out of the accessibility
    // tree as the `hidden` attribute alone would put it.
    if (selected) panel.removeAttribute('aria-hidden');
    else panel.setAttribute('aria-hidden', 'true');
  }
  // A hidden panel keeps its layout (style.css), so its plots keep their size; the shown ones
  // are sized in case the window changed meanwhile (a chart of the right size is left alone).
  if (name === 'plots') plots.resize();
  if (name === 'walkthrough') {
    walkthrough.shown();
    if (fetch) walkthroughView();
    walkthrough.plots.resize();
  }
  walkthrough.closeInspect();
}

/**
 * The largest value one voltage component can take under the scenario's limit, for the voltage
 * plot's limit lines: vmax for the box, v_dc/√3 for the circle, and the hexagon's vertex 2v_dc/3
 * for the hexagon (reached along the a axis only; elsewhere the hexagon is tighter).
 */
function componentLimit() {
  const shape = fieldValue(state.info, 'vlimit');
  if (shape === 'box' || shape === null) return Number(fieldValue(state.info, 'vmax'));
  const vdc = Number(fieldValue(state.info, 'vdc'));
  return shape === 'circle' ? vdc / Math.sqrt(3) : (2 * vdc) / 3;
}

/** The figures strip: each figure of the run with its unit and window (all from the core). */
// The figures the compact row shows, in this order.
const KEY_FIGURES = ['tracking_rms', 'current_peak', 'mean_nis', 'speed_error_final'];

/** The compact row of key figures that stands for the strip on small screens and projectors. */
function showKeyFigures(figures, rated) {
  const [low, high] = ['mean_nis_low', 'mean_nis_high'].map((n) => figures.find((f) => f.name === n));
  const parts = KEY_FIGURES.map((name) => figures.find((f) => f.name === name)).filter(Boolean).map((f) => {
    const value = `${Number(f.value.toPrecision(3))}${f.unit ? ` ${f.unit}` : ''}`;
    const span = document.createElement('span');
    if (f.name === 'current_peak' && rated) span.textContent = `peak |i_s| ${value} (${Number((f.value / rated.value).toPrecision(2))}× rated)`;
    else if (f.name === 'speed_error_final' && f.trend) {
      span.textContent = `final ω − ω_d ${value} (${{ settled: 'settled', changing: 'still changing', fluctuating: 'fluctuating' }[f.trend.state]})`;
      if (!f.trend.settled) span.className = 'unsettled';
    } else if (f.name === 'mean_nis' && low && high) {
      span.textContent = `mean NIS ${Number(f.value.toPrecision(4))} (${f.value >= low.value && f.value <= high.value ? 'inside' : 'outside'} its 95 % band)`;
    } else span.textContent = `${f.label} ${value}`;
    return span;
  });
  ui.keyFigures.replaceChildren(...parts.flatMap((p, i) => (i ? [' · ', p] : [p])));
  ui.figuresBar.hidden = parts.length === 0;
}

/**
 * Whether a final value `f` had settled, in words, from its trend over the end of the run:
 * [short text, the detail for its tooltip].
 */
function trendText(f) {
  const { rate, over, tolerance, scatter, state } = f.trend;
  const unit = f.unit ? ` ${f.unit}` : '';
  const fit = `line through the last ${Number((over * 1e3).toPrecision(3))} ms: ${Number(rate.toPrecision(3))}${unit} per s, the samples scattering ${Number(scatter.toPrecision(2))}${unit} about it; settled means both within ${Number(tolerance.toPrecision(2))}${unit}`;
  if (state === 'settled') return ['settled by the end of the run', fit];
  if (state === 'fluctuating') return [`fluctuating by ±${Number(scatter.toPrecision(2))}${unit}: the last sample is not a final value`, fit];
  return [`still changing: ${Number(rate.toPrecision(2))}${unit} per s at the end; run longer`, fit];
}

function showFigures(figures, warnings = []) {
  const fmt = (f) => {
    if (f.name === 'saturated_share') return `${Number((f.value * 100).toPrecision(3))} %`;
    if (f.unit === 's' && Math.abs(f.value) < 1) return `${Number((f.value * 1e3).toPrecision(4))} ms`;
    return `${Number(f.value.toPrecision(4))}${f.unit ? ` ${f.unit}` : ''}`;
  };
  const nis = Object.fromEntries(figures.filter((f) => f.name.startsWith('mean_nis')).map((f) => [f.name, f.value]));
  const rated = figures.find((f) => f.name === 'current_rated');
  const items = figures.filter((f) => !['mean_nis_low', 'mean_nis_high', 'current_rated'].includes(f.name)).map((f) => {
    let text = fmt(f);
    if (rated && ['current_peak', 'current_rms'].includes(f.name)) {
      text += ` (${Number((f.value / rated.value).toPrecision(3))}× the rated ${Number(rated.value.toPrecision(4))} A)`;
    }
    if (f.name === 'mean_nis' && 'mean_nis_low' in nis) {
      const inside = f.value >= nis.mean_nis_low && f.value <= nis.mean_nis_high;
      text += ` (95 % band ${Number(nis.mean_nis_low.toPrecision(3))}–${Number(nis.mean_nis_high.toPrecision(3))}: ${inside ? 'inside' : 'outside'})`;
    }
    const item = Object.assign(document.createElement('div'), { className: 'figure' });
    item.dataset.name = f.name;
    item.dataset.value = String(f.value);
    // A value read at the last sample says whether the run had settled by then.
    const trend = f.trend && trendText(f);
    if (f.trend) {
      Object.assign(item.dataset, { rate: String(f.trend.rate), settled: f.trend.settled ? '1' : '0' });
      if (!f.trend.settled) item.classList.add('unsettled');
    }
    if (f.name === 'mean_nis') Object.assign(item.dataset, { low: String(nis.mean_nis_low), high: String(nis.mean_nis_high) });
    if (f.name === 'current_peak' && rated) item.dataset.rated = String(rated.value);
    item.append(
      Object.assign(document.createElement('dt'), { textContent: f.label }),
      Object.assign(document.createElement('dd'), { textContent: text, title: `exact: ${f.value}${f.unit ? ` ${f.unit}` : ''}; ${f.window}` }),
      Object.assign(document.createElement('dd'), { className: 'window', textContent: f.window }),
    );
    if (trend) item.append(Object.assign(document.createElement('dd'), { className: 'trend', textContent: trend[0], title: trend[1] }));
    return item;
  });
  // What the figures must not be read without, in the core's words.
  // (A run that ran away says so in the message above, as a failure.)
  const warning = warnings.filter((w) => w.kind !== 'runaway').map((w) => w.text).join(' ');
  ui.consistency.textContent = warning;
  ui.consistency.hidden = !warning;
  ui.figures.replaceChildren(...items);
  ui.figures.hidden = items.length === 0;
  showKeyFigures(figures, rated);
  // The plots' text alternatives carry the same figures.
  const sentence = items.map((item) => `${item.querySelector('dt').textContent} ${item.querySelector('dd').textContent}`).join('; ');
  for (const set of plotSets) set.describe(sentence ? `Figures of this run: ${sentence}.${warning ? ` ${warning}` : ''}` : '');
}

/** The lines the PNG export carries above the plots: the scenario and the run's figures. */
function pngHeader() {
  const figures = state.figures.filter((f) => !f.name.startsWith('mean_nis_'))
    .map((f) => `${f.label} ${Number(f.value.toPrecision(4))}${f.unit ? ` ${f.unit}` : ''}`);
  const lines = [`IM Lab · ${state.info.encoded}`];
  for (let i = 0; i < figures.length; i += 3) lines.push(figures.slice(i, i + 3).join(' · '));
  return lines;
}

const handlers = {
  ready({ presets, nisBand }) {
    state.workerReady = true;
    // A worker started after a crash is ready too: the presets are listed already, and the
    // scenario stays as it is unless none was loaded yet.
    if (!state.presets.length) {
      state.presets = presets;
      state.nisBand = nisBand;
      for (const p of presets) ui.preset.append(Object.assign(document.createElement('option'), { value: p.name, textContent: p.name }));
    }
    if (state.info === null) load(scenarioFromUrl());
  },
  described({ req, info }) {
    state.pending.get(req)?.resolve(info);
    state.pending.delete(req);
  },
  invalid({ req, id, message }) {
    if (req !== undefined) {
      state.pending.get(req)?.reject(new Error(message));
      state.pending.delete(req);
    } else if (id === state.runId) {
      setBusy(false);
      say(message);
    }
  },
  progress({ id, done, total }) {
    if (id !== state.runId) return;
    ui.progress.value = done / total;
    ui.status.textContent = `Running: ${done.toLocaleString()} of ${total.toLocaleString()} samples`;
  },
  async done({ id, rows, failure, view, computeMs, stability, figures, transient, warnings }) {
    if (id !== state.runId) return;
    setBusy(false);
    ui.progress.value = 1;
    const arrived = performance.now();
    state.transient = transient;
    state.figures = figures;
    ui.fitLabel.textContent = transient
      ? `Fit y-axes after the start-up transient (t ≥ ${Number((transient.t * 1e3).toPrecision(3))} ms)`
      : 'Fit y-axes after the start-up transient';
    ui.fitLabel.title = transient?.reason ?? '';
    $('fit-reason').textContent = transient ? `Start-up transient: ${transient.reason}.` : '';
    showFigures(figures, warnings);
    if (view) {
      state.shownRun = id;
      walkthrough.show(stability, state.nisBand);
      // The walkthrough's plots are in the view once it has been opened.
      if (walkthrough.plots.defs.every((p) => p.id in view.plots)) walkthrough.receive(view);
      plots.show(view, { ifoc: ifocRun() });
      state.fitEmbed?.();
      // "Plotted" is when the browser has painted them: the canvases are rasterised then.
      await painted();
      // A newer run, or a worker crash while the plots were drawn, owns the page now.
      if (id !== state.runId || document.body.dataset.state === 'crashed') return;
      walkthroughView();
    }
    const ms = performance.now() - state.started;
    Object.assign(document.body.dataset, {
      plotMs: (performance.now() - arrived).toFixed(1), runMs: ms.toFixed(1), rows, computeMs: computeMs.toFixed(2), run: id,
    });
    ui.csv.disabled = ui.png.disabled = rows === 0;
    const ranAway = warnings.find((w) => w.kind === 'runaway');
    if (failure) {
      say(`The run stopped early: ${failure}. The plots show the ${rows.toLocaleString()} samples before it.`);
      ui.status.textContent = `Stopped after ${rows.toLocaleString()} samples`;
      document.body.dataset.state = 'failed';
    } else if (ranAway) {
      // The simulation completed, but as a control run it failed: say so before any figure.
      say(`${ranAway.text} The plots show what the motor did.`);
      ui.status.textContent = `Ran away: ${rows.toLocaleString()} samples in ${ms.toFixed(0)} ms`;
      document.body.dataset.state = 'failed';
    } else {
      ui.status.textContent = `${rows.toLocaleString()} samples in ${ms.toFixed(0)} ms`;
      document.body.dataset.state = 'done';
    }
    // Pins from a shared link are re-run once; afterwards each run refreshes the comparison.
    if (state.shared.pins && state.shared.pins.length > MAX_PINS_CHARS) {
      say(`The pins in the address were not run: ${state.shared.pins.length.toLocaleString()} characters, more than the ${MAX_PINS_CHARS.toLocaleString()} a pins fragment may hold.`);
      setFragment('pins', null);
    } else if (state.shared.pins) {
      const { scenarios, malformed } = decodePins(state.shared.pins);
      if (malformed.length) say(`Ignored a malformed pin in the address: ${listed(malformed.map((m) => `'${excerpt(m)}'`))}.`);
      // The core pins a few runs at most and names the rest; no more are sent than it can take.
      const sent = scenarios.slice(0, MAX_PINS_SENT);
      const dropped = scenarios.length - sent.length;
      if (dropped > 0) say(`Only the first ${MAX_PINS_SENT} pins in the address were run; ${dropped.toLocaleString()} more were left out.`);
      worker.postMessage({ type: 'pin', scenarios: sent, column: $('overlay-column').value });
    } else if (state.pins.length) {
      worker.postMessage({ type: 'pin', scenarios: [], column: $('overlay-column').value });
    }
    // A shared link with a sweep in its fragment runs that sweep once, after the first run.
    const shared = state.shared.sweep;
    state.shared = {};
    if (shared) {
      try {
        fillSweepForm(parseSweep(shared));
        showTab('analysis');
        runSweep();
      } catch (e) {
        say(`The sweep in the address (#sweep=${excerpt(shared)}) was not run: ${e.message}.`);
      }
    }
  },
  cancelled({ id }) {
    if (id !== state.runId) return;
    setBusy(false);
    ui.status.textContent = `Cancelled at ${(ui.progress.value * 100).toFixed(0)} %`;
    document.body.dataset.state = 'cancelled';
  },
  view({ id, set, view }) {
    if (id !== state.runId) return;
    if (set === 'walkthrough') {
      walkthrough.receive(view);
    } else {
      plots.refine(view);
      document.body.dataset.view = `${view.t0},${view.t1}`;
    }
  },
  inspected({ id, t, snapshot }) {
    if (id === state.runId) walkthrough.inspect(snapshot, t, Number(fieldValue(state.info, 'ts')));
  },
  compared({ id, results }) {
    if (id === state.runId) walkthrough.showComparison(results);
  },
  'pin-progress'({ index, count, done, total }) {
    state.pinning = true;
    ui.cancel.disabled = false;
    if (!state.running) {
      ui.progress.value = done / total;
      ui.status.textContent = `Running pin ${index + 1} of ${count}: ${((100 * done) / total).toFixed(0)} %`;
    }
    document.body.dataset.pinning = 'running';
  },
  pins({ scenarios, legends, rejected }) {
    if (state.pinning) {
      state.pinning = false;
      ui.cancel.disabled = !state.running && state.export === null;
      if (!state.running) ui.status.textContent = rejected.some((r) => /cancel/.test(r.message)) ? 'Pinning cancelled' : 'Pinned';
    }
    document.body.dataset.pinning = rejected.some((r) => /cancel/.test(r.message)) ? 'cancelled' : 'done';
    if (rejected.length) say(listed(rejected.map((r) => `could not pin ${excerpt(r.scenario)}: ${r.message}`), '; ').replace(/^c/, 'C') + '.');
    showPins(scenarios, legends);
  },
  overlay({ id, column, data }) {
    if (id === state.runId) drawOverlay(column, data);
  },
  crashed({ message }) {
    workerFailed(message);
  },
  async csv({ serial, bytes, rows, total }) {
    const job = state.export;
    if (job?.serial !== serial) return; // cancelled
    // Each chunk becomes a Blob at once: the browser keeps blob data out of the page's heap.
    const part = new Blob([bytes]);
    // Reading its last byte waits until the browser has stored the chunk, and fails if it refused
    // it (Chromium keeps at most 2 GiB of blobs where it cannot spill them to disk).
    try {
      await part.slice(-1).arrayBuffer();
    } catch (e) {
      if (state.export !== job) return;
      const stored = job.parts.reduce((sum, p) => sum + p.size, 0);
      endExport('failed', 'CSV export failed');
      say(`The browser refused to hold more than ${(stored / 1e6).toFixed(0)} MB of CSV (${e.name}). Export this run with the command line instead: imlab run '${state.ranScenario}' --out run.csv`);
      return;
    }
    if (state.export !== job) return; // cancelled meanwhile
    job.parts.push(part);
    ui.progress.value = total ? rows / total : 1;
    if (rows < total) {
      ui.status.textContent = `Exporting CSV: ${rows.toLocaleString()} of ${total.toLocaleString()} rows`;
      worker.postMessage({ type: 'csv-next', serial });
      return;
    }
    download(new Blob(job.parts, { type: 'text/csv' }), `${fileStem()}.csv`);
    endExport('done', `CSV exported: ${total.toLocaleString()} rows`);
  },
  'csv-failed'({ serial, message }) {
    if (state.export?.serial !== serial) return;
    endExport('failed', 'CSV export failed');
    say(`The CSV export failed: ${message}.`);
  },
};

/** Shows the pinned runs (with what differs from the current run) and keeps them in the link. */
function showPins(scenarios, legends) {
  state.pins = scenarios;
  setFragment('pins', scenarios.length ? scenarios.map(encodeURIComponent).join('|') : null);
  $('pins').replaceChildren(...scenarios.map((s, i) => {
    const unpin = Object.assign(document.createElement('button'), { type: 'button', textContent: 'Unpin' });
    unpin.addEventListener('click', () => worker.postMessage({ type: 'unpin', index: i }));
    const li = Object.assign(document.createElement('li'), { textContent: `pin ${i + 1}: ${legends[i] ?? ''}` });
    li.append(unpin);
    return li;
  }));
  requestOverlay();
}

// A preset chosen with the mouse runs at once; one reached with the arrow keys runs when it is
// committed (Enter, or leaving the picker), so stepping through the list starts no runs.
let presetByKeyboard = false;
// Keys that move through the list without choosing; Enter (also from the open list) chooses.
const BROWSE = new Set(['ArrowUp', 'ArrowDown', 'ArrowLeft', 'ArrowRight', 'Home', 'End', 'PageUp', 'PageDown']);
ui.preset.addEventListener('keydown', (e) => {
  presetByKeyboard = BROWSE.has(e.key) || e.key.length === 1;
  if (e.key === 'Enter' && state.presetPending) commitPreset();
});
ui.preset.addEventListener('pointerdown', () => { presetByKeyboard = false; });
ui.preset.addEventListener('change', () => {
  state.presetPending = true;
  if (!presetByKeyboard) commitPreset();
});
ui.preset.addEventListener('blur', () => state.presetPending && commitPreset());
function commitPreset() {
  state.presetPending = false;
  load(`v=1&preset=${ui.preset.value}`);
}
ui.form.addEventListener('change', formChanged);
// Enter in a settings field runs the scenario (a form of many fields and no submit button has no
// implicit submission, so Enter is taken here).
ui.form.addEventListener('keydown', (e) => {
  if (e.key !== 'Enter' || !e.target.matches('input, select')) return;
  e.preventDefault();
  runForm();
});
ui.form.addEventListener('submit', (e) => {
  e.preventDefault();
  runForm();
});
// A walkthrough knob re-runs on change, on Enter, or after a pause in typing.
const walk = $('walkthrough');
walk.addEventListener('change', (e) => e.target.closest('.knobs') && knobChanged(e.target));
walk.addEventListener('keydown', (e) => {
  if (e.key === 'Enter' && e.target.closest('.knobs')) {
    e.preventDefault();
    knobChanged(e.target);
  }
});
walk.addEventListener('input', (e) => {
  if (!e.target.closest('.knobs') || e.target.type === 'checkbox') return;
  clearTimeout(state.knobTimer);
  state.knobTimer = setTimeout(() => knobChanged(e.target), 800);
});
ui.fullRun.addEventListener('click', fullRun);
ui.figuresToggle.addEventListener('click', () => {
  const open = !ui.figures.classList.contains('open');
  ui.figures.classList.toggle('open', open);
  ui.figuresToggle.setAttribute('aria-expanded', String(open));
  ui.figuresToggle.textContent = open ? 'Fewer figures' : 'All figures';
});
ui.fit.addEventListener('change', () => {
  plotSets.forEach((p) => p.refit());
  analysis.refit();
});
document.addEventListener('keydown', (e) => {
  if (e.key !== 'Escape') return;
  if (!ui.inspect.hidden) walkthrough.closeInspect();
  else if (document.body.classList.contains('settings-open')) {
    openSettings(false);
    ui.settingsToggle.focus();
  } else fullRun();
});
// An edit still being checked by the core must land before the run starts.
async function runForm() {
  if (composeScenario(ui.form, ui.preset.value) !== state.composed && !(await formChanged())) return;
  if (!ui.run.disabled) startRun();
}
ui.run.addEventListener('click', runForm);
// Cancel stops the run or the CSV export, whichever is under way.
ui.cancel.addEventListener('click', () => {
  if (state.pinning && !state.running) worker.postMessage({ type: 'pin-cancel' });
  else if (state.export) cancelExport('CSV export cancelled');
  else worker.postMessage({ type: 'cancel', id: state.runId });
});
ui.csv.addEventListener('click', startExport);
ui.png.addEventListener('click', async () => {
  const tab = document.querySelector('[role=tab][aria-selected=true]').dataset.tab;
  const set = tab === 'walkthrough' ? walkthrough.plots : plots;
  if (set.charts.length === 0 || (tab === 'walkthrough' && !walkthrough.drawn())) {
    say('These plots are still being drawn; export them in a moment.', 'info');
    return;
  }
  download(await png(set.figures(), pngHeader()), `${fileStem()}.png`);
});
ui.copy.addEventListener('click', async () => {
  try {
    await navigator.clipboard.writeText(location.href);
    say('Link copied: it reproduces this run bit for bit.', 'info');
  } catch {
    say(`Copy this link: ${location.href}`, 'info');
  }
});
for (const tab of TABS) tab.addEventListener('click', () => showTab(tab.dataset.tab));
// Arrow keys, Home and End move between tabs and select them.
document.querySelector('[role=tablist]').addEventListener('keydown', (e) => {
  const i = TABS.indexOf(document.activeElement);
  const to = { ArrowRight: i + 1, ArrowLeft: i - 1, Home: 0, End: TABS.length - 1 }[e.key];
  if (i < 0 || to === undefined) return;
  e.preventDefault();
  const tab = TABS[(to + TABS.length) % TABS.length];
  showTab(tab.dataset.tab);
  tab.focus();
});

/** Presentation mode: larger text and plots, settings in the drawer; kept in the URL fragment. */
function present(on) {
  document.body.classList.toggle('present', on);
  ui.present.setAttribute('aria-pressed', on);
  setFragment('present', on ? '1' : null);
  const [main, small] = PLOT_HEIGHT[on ? 'present' : 'normal'];
  const scale = on ? PRESENT_SCALE : 1;
  plots.rescale(scale, main);
  walkthrough.plots.rescale(scale, small);
  openSettings(false);
}
ui.present.addEventListener('click', () => present(!document.body.classList.contains('present')));

/** Opens or closes the settings drawer (presentation mode and small screens). */
function openSettings(open) {
  document.body.classList.toggle('settings-open', open);
  ui.settingsToggle.setAttribute('aria-expanded', open);
}
ui.settingsToggle.addEventListener('click', () => openSettings(!document.body.classList.contains('settings-open')));

// An embed (`#embed=PLOT,PLOT...`) shows those plots of the Trajectories tab with Run and the key
// figures, the plots sharing the frame's height, so that the frame holds them at any size.
const embedded = fragment('embed');
if (embedded !== null) {
  const asked = embedded.split(',').slice(0, PLOTS.length);
  const ids = asked.filter((id) => PLOTS.some((p) => p.id === id));
  const unknown = asked.filter((id) => !ids.includes(id));
  if (ids.length === 0) ids.push('speed');
  document.body.classList.add('embed');
  document.body.dataset.embed = ids.join(',');
  plots.embedded = ids;
  for (const div of ui.plots.querySelectorAll('.plot[data-plot]')) div.classList.toggle('embedded', ids.includes(div.dataset.plot));
  // Kept until the user acts: a load's message would otherwise clear it.
  if (unknown.length) state.notice = `No plot named ${unknown.map((id) => `'${excerpt(id)}'`).join(', ')}; showing ${ids.join(', ')}. Plots: ${PLOTS.map((p) => p.id).join(', ')}.`;
  say(state.notice ?? '', 'info');
  state.fitEmbed = () => plots.resize(embedHeight(ids.length));
  window.addEventListener('resize', state.fitEmbed);
}
if (fragment('present') === '1') {
  document.body.classList.add('present');
  ui.present.setAttribute('aria-pressed', true);
  plots.scale = walkthrough.plots.scale = PRESENT_SCALE;
  [plots.height, walkthrough.plots.height] = PLOT_HEIGHT.present;
}

/**
 * Height of each of `n` embedded plots: together they fill the frame under the run row. What is
 * not plot (the run row, the key figures, titles and legends) is measured from the page as laid
 * out, down to the last plot's bottom and a margin.
 */
function embedHeight(n) {
  const shown = [...ui.plots.querySelectorAll('.plot.embedded')];
  if (shown.length === 0) return plots.height;
  const bottom = Math.max(...shown.map((p) => p.getBoundingClientRect().bottom)) + scrollY + EMBED_MARGIN;
  return Math.max(EMBED_MIN_HEIGHT, Math.floor(plots.height + (innerHeight - bottom) / n));
}

/** The Trajectories plots the user is looking at: those at least half in view, else the speed plot. */
function plotsInView() {
  if (ui.plots.offsetParent === null) return ['speed'];
  const inView = [...ui.plots.querySelectorAll('.plot[data-plot]')].filter((p) => {
    const box = p.getBoundingClientRect();
    const shown = Math.min(box.bottom, innerHeight) - Math.max(box.top, 0);
    return box.height > 0 && shown >= box.height / 2;
  }).map((p) => p.dataset.plot);
  return inView.length ? inView : ['speed'];
}

ui.embed.addEventListener('click', async () => {
  const ids = plotsInView();
  const src = `${location.origin}${location.pathname}?${state.info.encoded}#embed=${ids.join(',')}`;
  const title = `IM Lab: ${presetNamed(state.info.encoded)}, ${ids.join(', ')}`.replace(/[&<"]/g, (c) => `&#${c.charCodeAt(0)};`);
  // The plots share whatever height the frame has; this one gives each about 300 px.
  const height = 140 + 300 * ids.length;
  const code = `<iframe src="${src.replaceAll('"', '%22')}" title="${title}" width="100%" height="${height}" style="border:0;max-width:960px" loading="lazy"></iframe>`;
  const what = `the ${ids.join(', ')} plot${ids.length > 1 ? 's' : ''} of this run (the Trajectories plots in view)`;
  try {
    await navigator.clipboard.writeText(code);
    say(`Embed code copied: ${what}. Paste it into a slide or a course page.`, 'info');
  } catch {
    say(`Copy this embed code for ${what}: ${code}`, 'info');
  }
});
window.addEventListener('popstate', () => load(scenarioFromUrl()));
window.addEventListener('resize', () => {
  plots.resize();
  walkthrough.plots.resize();
});

const sweepForm = $('sweep-form');

function readSweepForm() {
  const f = sweepForm.elements;
  const num = (name) => Number(f.namedItem(name).value);
  return {
    lo: num('lo'), hi: num('hi'), n: num('n'), amp: num('amp'), offset: num('offset'), duration: num('duration'),
    variants: [...sweepForm.querySelectorAll('[name=variant]:checked')].map((c) => c.value),
    workers: num('workers'),
  };
}

function fillSweepForm(s) {
  for (const key of ['lo', 'hi', 'n', 'amp', 'offset', 'duration']) sweepForm.elements.namedItem(key).value = s[key];
  for (const c of sweepForm.querySelectorAll('[name=variant]')) c.checked = s.variants.includes(c.value);
}

async function runSweep() {
  const settings = readSweepForm();
  const status = $('sweep-status');
  if (!settings.variants.length) {
    status.textContent = 'Choose at least one variant.';
    return;
  }
  if (!isCount(settings.n)) {
    status.textContent = `points = ${sweepForm.elements.namedItem('n').value}: expected a whole number.`;
    return;
  }
  if (!(Number.isInteger(settings.workers) && settings.workers >= 1 && settings.workers <= 8)) {
    status.textContent = `workers = ${sweepForm.elements.namedItem('workers').value}: expected a whole number from 1 to 8.`;
    return;
  }
  setFragment('sweep', formatSweep(settings));
  $('sweep-run').disabled = true;
  $('sweep-cancel').disabled = false;
  const started = performance.now();
  status.textContent = 'Sweeping…';
  try {
    const out = await analysis.sweep(settings, {
      workers: settings.workers,
      onProgress: (p) => { $('sweep-progress').value = p; },
    });
    analysis.showSweep(out, $('bode'), $('sweep-table'));
    const ms = performance.now() - started;
    status.textContent = `${settings.variants.length} × ${settings.n} runs in ${ms.toFixed(0)} ms on ${settings.workers} worker${settings.workers > 1 ? 's' : ''}.`;
    if (settings.variants.some((v) => v.startsWith('ifoc')) && Math.abs(settings.offset) < 20) {
      status.textContent += ' The IFOC figures are not meaningful here: its MRAS cannot estimate the speed near standstill. Sweep it about an operating speed (offset ≥ 20 rad/s) with longer runs (3 s).';
    }
    Object.assign(document.body.dataset, { sweep: 'done', sweepMs: ms.toFixed(1) });
    $('sweep-csv').disabled = false;
  } catch (e) {
    status.textContent = e.message === 'cancelled' ? 'Sweep cancelled.' : `Sweep failed: ${e.message}`;
    document.body.dataset.sweep = e.message === 'cancelled' ? 'cancelled' : 'failed';
  } finally {
    $('sweep-run').disabled = false;
    $('sweep-cancel').disabled = true;
  }
}

async function runSeeds() {
  const n = Number($('seeds-form').elements.namedItem('n').value);
  const status = $('seeds-status');
  if (!(Number.isInteger(n) && n >= 1 && n <= 1000)) {
    status.textContent = `seeds = ${$('seeds-form').elements.namedItem('n').value}: expected a whole number from 1 to 1000.`;
    return;
  }
  status.textContent = 'Running seeds…';
  const progress = $('seeds-progress');
  progress.value = 0;
  $('seeds-cancel').disabled = false;
  document.body.dataset.seeds = 'running';
  try {
    const first = Number(fieldValue(state.info, 'seed'));
    const out = await analysis.seeds(n, first, state.info.steps, (p) => {
      progress.value = p;
      status.textContent = `Running seeds: ${(p * 100).toFixed(0)} %`;
    });
    analysis.showSeeds(out, $('seeds-plots'), framing);
    state.seedsCsv = out.csv;
    $('seeds-csv').disabled = false;
    status.textContent = `${out.bands.runs} of ${n} seeds (${first} to ${first + n - 1}) completed.`;
    document.body.dataset.seeds = 'done';
  } catch (e) {
    const cancelled = e.message === 'cancelled';
    status.textContent = cancelled ? 'Seed runs cancelled.' : `Seed sweep failed: ${e.message}`;
    document.body.dataset.seeds = cancelled ? 'cancelled' : 'failed';
  } finally {
    $('seeds-cancel').disabled = true;
  }
}

$('pin').addEventListener('click', () => worker.postMessage({ type: 'pin', scenarios: [state.info.encoded], column: $('overlay-column').value }));
$('overlay-column').addEventListener('change', requestOverlay);
$('sweep-run').addEventListener('click', runSweep);
$('sweep-cancel').addEventListener('click', () => analysis.pool.cancel());
$('sweep-csv').addEventListener('click', async () => {
  const first = Object.keys(analysis.points)[0];
  download(new Blob([await analysis.sweepCsv(first)], { type: 'text/csv' }), `imlab-sweep-${first}.csv`);
});
$('seeds-run').addEventListener('click', runSeeds);
$('seeds-cancel').addEventListener('click', () => analysis.pool.cancel());
$('seeds-csv').addEventListener('click', () => download(new Blob([state.seedsCsv], { type: 'text/csv' }), 'imlab-seeds.csv'));

// The page's plot sets, for the browser tests and the console.
window.imlab = { plots, walkthrough: walkthrough.plots, overlay: null };

setBusy(false);
startWorker();
// While the worker loads the core, the main plots are laid out, empty, and their drawing code is
// compiled.
plots.prepare();
plots.warm();
navigator.serviceWorker?.register('sw.js');
