// Page wiring: one worker owns the core; the page sends scenarios and draws what comes back.
// This file composes the page's parts, each in its own module, and wires them to each other.
import { Plots, mainPlots } from './plots/plots.js';
import { buildGroups } from './run/controls.js';
import { fieldValue } from './ui/scenario.js';
import { challengeFromUrl, fragment, scenarioFromUrl, setFragment } from './ui/url.js';
import { excerpt } from './ui/quote.js';
import { Analysis } from './analysis/analysis.js';
import { Walkthrough } from './teaching/walkthrough.js';
import { loadTex } from './teaching/tex.js';
import { LessonPanel } from './teaching/lessons.js';
import { LESSONS } from './teaching/teaching.js';
import { $, say, ui } from './ui/page.js';
import { whenIdle } from './ui/dom.js';
import { RunClient, ScenarioRefused } from './client/run-client.js';
import { createRun } from './run/run.js';
import { createSettings } from './run/settings.js';
import { createViews } from './run/views.js';
import { createFiguresView } from './run/figures-view.js';
import { createExport } from './run/export.js';
import { createPins } from './run/pins.js';
import { createTabs } from './ui/tabs.js';
import { createPresentation } from './ui/presentation.js';
import { wireShare } from './ui/share.js';
import { createSweeps } from './analysis/sweeps.js';
import { wireMotor } from './analysis/motor.js';
import { createRobust } from './analysis/robust.js';
import { ChallengePanel } from './challenge/challenge.js';
import { listBuiltins } from './challenge/builtins.js';
import { createStale } from './ui/stale.js';
import { chooseLanguage, languageFiles, loadRest, t, useLanguage } from './l10n/l10n.js';
import { wireLanguageMenu } from './ui/language.js';

/** @import * as P from './worker/protocol.js' */
/** @import { Unreached } from './run/figures-view.js' */

/**
 * Lists the built-in challenges in the Lessons tab, once: when the page is idle after the first run
 * or when the tab is first opened, whichever comes first (their listing loads the core's tools,
 * which the first run does not need).
 */
let challengesListed = false;
function listChallenges() {
  if (challengesListed) return;
  challengesListed = true;
  listBuiltins(client, $('challenges'));
}

/**
 * Registers the service worker, once, after the first run is drawn: it then fetches the files the
 * page loads later (the tools, KaTeX) without taking the network from the first plot.
 */
let swRegistered = false;
function registerServiceWorker() {
  if (swRegistered) return;
  swRegistered = true;
  // Where the browser allows no service worker (a page opened from a file, an embed in another
  // site's page whose storage the browser partitions or blocks, some private windows), the page
  // works while online only: that is said in the lecturer's guide, not logged as an error.
  const refused = () => (document.body.dataset.offline = 'refused');
  try {
    // A sandboxed frame refuses even the look at navigator.serviceWorker.
    navigator.serviceWorker?.register('sw.js').then(async () => {
      // Kept offline: the language shown, not the others; said once the worker has kept them.
      const worker = (await navigator.serviceWorker.ready).active;
      if (!worker) return refused();
      const channel = new MessageChannel();
      const kept = new Promise((resolve) => (channel.port1.onmessage = (e) => resolve(e.data?.kept === true)));
      worker.postMessage({ keep: languageFiles() }, [channel.port2]);
      document.body.dataset.offline = (await kept) ? 'kept' : 'failed';
    }, refused);
  } catch {
    refused();
  }
}

/**
 * The page's shared state: `state` below, whose fields are described there.
 * @typedef {{
 *   info: P.Info | null,
 *   nisBand: [number, number],
 *   notice: string | null,
 *   runId: number,
 *   running: boolean,
 *   ranScenario: string | null,
 *   ranLaws: boolean,
 *   shownRun: number,
 *   transient: {t: number, reason: string} | null,
 *   figures: P.RunFigure[],
 *   unreached: Unreached[],
 *   export: {serial: number, parts: Blob[]} | null,
 *   pins: string[],
 *   pinning: boolean,
 * }} State
 */

// What the page's parts share; in brackets, the parts that write each field.
/** @type {State} */
const state = {
  info: null, // the core's description of the scenario in the form (settings)
  nisBand: [0, 0], // the NIS band, from the core (settings)
  notice: null, // a notice about the link that stays until the user acts (presentation; run ends it)
  runId: 0, // runs started (run)
  running: false, // a run is being computed (run)
  ranScenario: null, // the scenario of the last run started (run)
  ranLaws: false, // whether it has own laws for the backstepping steps (run)
  shownRun: 0, // the run the plots show (run)
  transient: null, // {t, reason}: the end of the start-up transient, from the core (run)
  figures: [], // the run's figures, from the core (run)
  unreached: [], // the figures the run had not reached by its end, from the core (run)
  export: null, // the CSV export under way: {serial, parts: [Blob]} (export)
  pins: [], // pinned scenarios, in pin order (pins)
  pinning: false, // pins are being run in the worker (pins; run, when the worker fails)
};
/** Whether the y-axes leave out the start-up transient, and from which time. */
const framing = () => ({ fit: ui.fit.checked && state.transient !== null, from: state.transient?.t ?? -Infinity });
const sampleTime = () => Number(fieldValue(state.info, 'ts')) || null;

/**
 * The worker's messages handled by the page's parts, by type: one part a type. Two parts that
 * would handle the same type are a mistake of the page, refused rather than one silently lost.
 * @param {...{handlers: P.Handlers}} parts
 * @returns {P.Handlers}
 */
function handlersOf(...parts) {
  /** @type {Record<string, unknown>} */
  const handlers = {};
  for (const part of parts) {
    for (const [type, handle] of Object.entries(part.handlers)) {
      if (Object.hasOwn(handlers, type)) throw new Error(`two parts of the page handle the worker's '${type}'`);
      handlers[type] = handle;
    }
  }
  return /** @type {P.Handlers} */ (handlers);
}

// The page speaks the link's language (`#lang=`), else the first of the browser's it speaks. A
// language whose messages cannot be fetched (offline, before they were kept) leaves it in English,
// whose page messages are kept offline with any language's. Should those fail too, the page still
// works, with the English written into it and its other messages' names.
const asked = chooseLanguage(fragment('lang'), navigator.languages);
try {
  await useLanguage(asked);
} catch (e) {
  await useLanguage('en').catch((again) => console.error(`no page messages: ${again.message}`));
  state.notice = t('page-language-failed', { language: asked, reason: /** @type {Error} */ (e).message });
  say(state.notice, 'info');
}
wireLanguageMenu();

const client = new RunClient(
  /**
   * @param {string} reason
   * @param {boolean} restarting
   */
  (reason, restarting) => {
    run.workerFailed(reason, restarting);
    if (restarting) pins.show([], []);
  },
);
const plots = new Plots(ui.plots, mainPlots(), {
  onWindow: (t0, t1) => views.requestWindow(t0, t1),
  onFull: () => views.fullRun(),
  onPick: (t) => views.requestInspect(t),
  sampleTime,
  framing,
  // Constant lines are drawn with a run's plots, after its scenario was described.
  constants: (plot) =>
    plot.constants ? [1, -1].map((s) => s * /** @type {P.Info} */ (state.info).component_limit) : [],
  lazy: true,
});
const walkthrough = new Walkthrough({
  container: $('walkthrough'),
  form: ui.form,
  inspectBox: ui.inspect,
  knob: (/** @type {string} */ key) => settings.knob(key),
  onCompare: () => views.compare(),
  onWindow: (/** @type {number} */ t0, /** @type {number} */ t1) => views.requestWindow(t0, t1),
  onFull: () => views.fullRun(),
  onPick: (/** @type {number} */ t) => views.requestInspect(t),
  framing,
  // The editor of a step's own law asks the core built with its tools (fetched on the first).
  preview: (/** @type {number} */ step, /** @type {string} */ text) => client.job('law-preview', { step, text }),
  language: () => client.job('law-language'),
});
walkthrough.plots.sampleTime = sampleTime;
walkthrough.onInspect = (t) => {
  plots.mark(t);
  walkthrough.plots.mark(t);
};
// Built after the first run, the walkthrough's knobs then follow an open challenge's locks.
walkthrough.onBuilt = () => challenge.lock();
// So do the settings' closed groups, built after the first run or when one is opened (controls.js).
ui.form.addEventListener('fieldsbuilt', () => challenge.lock());
const plotSets = [plots, walkthrough.plots];
// The analyses run the scenario the core last described.
const analysis = new Analysis({ scenario: () => /** @type {P.Info} */ (state.info).encoded, client });
// The long results keep the scenario they were computed for and are marked while it is not the
// settings'; an analysis first makes the settings the run on screen.
const stale = createStale({ state, load: (/** @type {string} */ scenario) => settings.load(scenario) });
const views = createViews({ client, state, plots, walkthrough, stale });
const presentation = createPresentation({ state, plots, walkthrough, rescaled: () => robust.redraw() });
const figuresView = createFiguresView({ plotSets });
const exporter = createExport({ client, state, plots, walkthrough });
const pins = createPins({ client, state, plots });
const tabs = createTabs({ plots, walkthrough, walkthroughView: views.walkthroughView });
// KaTeX is fetched when an equation is first shown; a pointer over the walkthrough's tab, or the
// keyboard's focus on it, starts the fetch a moment sooner.
for (const event of ['pointerenter', 'focus'])
  $('tab-walkthrough', HTMLButtonElement).addEventListener(event, () => loadTex().catch(() => {}), { once: true });
$('tab-lessons', HTMLButtonElement).addEventListener('click', listChallenges, { once: true });
/** Lists the lessons, with their texts fetched in the language shown; a failed fetch is said. */
const listLessons = () =>
  lessons.texts().catch((e) => say(t('lessons-not-loaded', { reason: /** @type {Error} */ (e).message })));
for (const event of ['pointerenter', 'focus', 'click'])
  $('tab-lessons', HTMLButtonElement).addEventListener(event, listLessons, { once: true });
const current = () => settings.runCurrent();
const sweeps = createSweeps({ state, analysis, framing, showTab: tabs.showTab, current, stale });
// Shows the plots of a scenario, run (a map's cell, a motor of one's own).
const openRun = (/** @type {string} */ scenario) => (tabs.showTab('plots'), settings.load(scenario));
const robust = createRobust({
  state,
  analysis,
  showTab: tabs.showTab,
  current,
  stale,
  open: openRun,
  scale: () => plots.scale,
  // A lesson about the map shows it as it is drawn.
  drawn: () => lessons.mapDrawn(),
});
wireMotor({ client, open: openRun });
const challenge = new ChallengePanel({
  client,
  state,
  relayout: () => plotSets.forEach((p) => p.resize()),
  stale,
});
/**
 * The Challenge tab's composer and class grading, fetched when the tab is first pointed at or
 * shown, or the page is idle after its first run: the first plot waits for neither. Their buttons
 * are off until then. A failed fetch is said, and tried again on the next of those.
 * @type {Promise<void> | null}
 */
let challengeTools = null;
function loadChallengeTools() {
  challengeTools ??= Promise.all([
    import('./challenge/challenge-compose.js'),
    import('./challenge/grade.js'),
    loadRest(),
  ]).then(
    ([compose, grading]) => {
      compose.createCompose({ client, state });
      grading.createGrading({ client });
    },
    (e) => {
      challengeTools = null;
      say(t('page-challenge-tools-failed', { reason: e.message }));
    },
  );
  return challengeTools;
}
for (const event of ['pointerenter', 'focus', 'click'])
  $('tab-challenge', HTMLButtonElement).addEventListener(event, loadChallengeTools);
const run = createRun({
  client,
  state,
  plots,
  walkthrough,
  views,
  figuresView,
  exporter,
  fitEmbed: presentation.fitEmbed,
  afterRun: () => {
    // What no one sees yet is built once the page is idle, unless it is shown first, with the rest
    // of the page's messages.
    whenIdle(() => {
      loadRest().catch((e) => say(t('page-messages-failed', { reason: e.message })));
      loadChallengeTools();
      walkthrough.build();
      buildGroups(ui.form);
      listChallenges();
      listLessons();
    });
    registerServiceWorker();
    pins.afterRun();
    sweeps.afterRun();
    robust.afterRun();
    challenge.check();
    lessons.afterRun();
  },
});
const settings = createSettings({
  client,
  state,
  walkthrough,
  startRun: run.start,
  markUnrun: run.markUnrun,
  openSettings: presentation.openSettings,
  first: () => (lessonFromUrl() ? null : challenge.open()),
  described: (info) => {
    challenge.described(info);
    stale.follow();
  },
  mayRun: (info) => challenge.mayRun(info),
});
const lessons = new LessonPanel({
  panel: $('lesson-panel'),
  list: $('lessons'),
  lessons: LESSONS,
  /**
   * @param {{run: string, tab?: string, map?: string}} lesson a lesson of teaching.js, its texts rendered
   * @param {string | null} link the address's scenario, when the address names the lesson
   */
  onOpen: (lesson, link) => {
    // A lesson starts from its own state: no runs pinned in another lesson stay in its overlay.
    pins.clear();
    // The lesson's own run brings the walkthrough's view; the last run's is not asked for.
    tabs.showTab(lesson.tab ?? 'plots', { fetch: false });
    if (lesson.map) robust.fill(lesson.map).catch((e) => say(t('page-lesson-map-failed', { reason: e.message })));
    window.scrollTo(0, 0);
    return settings.load(link ?? lesson.run);
  },
  differences: (lesson, link) => differencesFrom(lesson.run, link),
  draw: (plot) => plotSets.forEach((set) => set.draw(plot)),
});

/**
 * How scenario `text` differs from scenario `from`, a line a field as the core writes it; one line
 * saying the core refused `text`, or that the two could not be compared, when so.
 * @param {string} from
 * @param {string} text
 * @returns {Promise<string[]>}
 */
async function differencesFrom(from, text) {
  try {
    await client.describe(text);
  } catch (e) {
    return e instanceof ScenarioRefused
      ? [t('lesson-differences-refused', { reason: /** @type {Error} */ (e).message })]
      : [];
  }
  return client.job('scenario-differences', { from, text }).catch(() => [t('lesson-differences-uncompared')]);
}
wireShare({ state });

/**
 * Opens the lesson the address names (`#lesson=ID`), with its run, unless a challenge link holds
 * the address; returns whether it did. An unknown name is said, with the names there are.
 */
function lessonFromUrl() {
  const id = fragment('lesson');
  if (id === null || challengeFromUrl()) return false;
  if (lessons.openById(id, location.search.slice(1) || null)) return true;
  setFragment('lesson', null);
  state.notice = t('page-no-lesson', { lesson: excerpt(id), lessons: LESSONS.map((l) => l.id).join(', ') });
  say(state.notice, 'info');
  return false;
}
client.handlers = handlersOf(settings, run, views, pins, exporter);

ui.fullRun.addEventListener('click', views.fullRun);
ui.fit.addEventListener('change', () => {
  plotSets.forEach((p) => p.refit());
  analysis.refit();
});
document.addEventListener('keydown', (e) => {
  if (e.key !== 'Escape') return;
  if (!ui.inspect.hidden) walkthrough.closeInspect();
  else if (document.body.classList.contains('settings-open')) {
    presentation.openSettings(false);
    ui.settingsToggle.focus();
  } else views.fullRun();
});
// Cancel stops the run, the pins being run or the CSV export, whichever is under way.
ui.cancel.addEventListener('click', () => {
  if (state.pinning && !state.running) client.post({ type: 'pin-cancel' });
  else if (state.export) exporter.cancel(t('export-csv-cancelled'));
  else client.post({ type: 'cancel', id: state.runId });
});
// An open challenge holds the address (url.js): its entries are not scenarios to go back to.
// Back and Forward show the lesson the entry names, if any, with the entry's scenario.
window.addEventListener('popstate', () => {
  if (challenge.active()) return;
  lessons.follow(fragment('lesson'));
  settings.load(scenarioFromUrl());
});
window.addEventListener('resize', () => {
  plots.resize();
  walkthrough.plots.resize();
});

// The page's plot sets, for the browser tests and the console.
window.imlab = { plots, walkthrough: walkthrough.plots, overlay: null, map: robust.chart };

run.setBusy(false);
client.start();
settings.loadFirst();
// While the worker loads the core, the main plots' figures are laid out, empty.
plots.prepare();
