// The scenario in the settings form: loading one (from the address, a preset, history or a
// lesson), checking each edit of the form or of a walkthrough knob with the core, the preset
// picker, and Run.
import { $, say, ui } from '../ui/page.js';
import { composeScenario, fieldControl, forwardKnob, markInvalid, renderFields } from './controls.js';
import { WorkerFailed } from '../client/run-client.js';
import { DEFAULT_SCENARIO, listed, presetNamed, scenarioFromUrl, showScenario } from '../ui/url.js';

// Keys that move through the preset list without choosing; Enter (also from the open list) chooses.
const BROWSE = new Set(['ArrowUp', 'ArrowDown', 'ArrowLeft', 'ArrowRight', 'Home', 'End', 'PageUp', 'PageDown']);

function syncControl(control, value) {
  if (!control || control === document.activeElement) return;
  if (control.type === 'checkbox') control.checked = value === '1';
  else control.value = value;
}

/**
 * The settings; `startRun()` and `markUnrun(unrun)` are the run's, `openSettings(open)` opens the
 * settings drawer. The worker's `ready` message (`handlers`) lists the presets and loads the
 * scenario `first()` resolves with (the address's, unless a challenge gives it). `described(info)`
 * follows every description the form takes.
 */
export function createSettings({
  client,
  state,
  walkthrough,
  startRun,
  markUnrun,
  openSettings,
  first = scenarioFromUrl,
  described = () => {},
}) {
  let presets = []; // the core's presets: {name, description}
  let composed = null; // the scenario the form held when last checked
  let checking = Promise.resolve(true); // that check: whether the core accepted it
  let knobTimer = null; // a pause in typing in a knob, after which it is checked
  const knobIds = new Map(); // walkthrough knobs given out per field, for unique ids
  let presetPending = false; // the picker moved by keyboard, not yet committed
  // A preset chosen with the mouse runs at once; one reached with the arrow keys runs when it is
  // committed (Enter, or leaving the picker), so stepping through the list starts no runs.
  let presetByKeyboard = false;

  // A field can be a knob in several sections: the first is `knob-KEY`, later ones
  // `knob-KEY-2`, ... (ids stay unique; the ids given out are counted per description).
  function knob(key) {
    const f = state.info?.fields.find((x) => x.key === key && x.value !== null && x.acts);
    if (!f) return null;
    const n = (knobIds.get(key) ?? 0) + 1;
    knobIds.set(key, n);
    return fieldControl(f, n === 1 ? 'knob' : `knob${n}`);
  }

  function applyDescription(info) {
    const shown = (i) =>
      i?.fields
        .filter((f) => f.value !== null)
        .map((f) => `${f.key}${f.acts ? '' : '-'}`)
        .join();
    const keysBefore = shown(state.info);
    const keysAfter = shown(info);
    const presetChanged = ui.preset.value !== presetNamed(info.encoded);
    state.info = info;
    knobIds.clear();
    if (keysBefore !== keysAfter || presetChanged) renderFields(ui.form, info);
    else for (const f of info.fields) if (f.value !== null) syncControl(ui.form.elements.namedItem(f.key), f.value);
    walkthrough.describe(info);
    ui.preset.value = presetNamed(info.encoded);
    // The preset's description, and what this run changes of it (a lesson's run may hold another
    // speed or length than the preset says).
    const changed = info.changed;
    const description = presets.find((p) => p.name === ui.preset.value)?.description ?? '';
    ui.presetDoc.textContent = changed.length
      ? `${description}. This run changes: ${changed.join(', ')}.`
      : description;
    ui.run.disabled = state.running;
    markInvalid(ui.form, null);
    described(info);
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
      const info = await client.describe(text);
      say(state.notice ?? '', 'info');
      return info;
    } catch (e) {
      if (e instanceof WorkerFailed) throw e;
      try {
        // Keep what is valid; name every field that was left out.
        const info = await client.describe(text, 'recover');
        say(
          `Some settings in the address were rejected and left at the preset's values: ${listed(info.rejected, '; ')}.`,
        );
        return info;
      } catch (again) {
        if (again instanceof WorkerFailed) throw again;
        say(
          `The scenario in the address was rejected: ${e.message}. Showing ${presetNamed(DEFAULT_SCENARIO)} instead.`,
        );
        return client.describe(DEFAULT_SCENARIO);
      }
    }
  }

  /** Checks the form's scenario with the core; resolves with whether it is valid. An invalid value
   * is marked at its field, and at the walkthrough knob when a knob was edited. */
  function formChanged() {
    checking = checkForm();
    return checking;
  }

  async function checkForm() {
    const text = composeScenario(ui.form, ui.preset.value);
    composed = text;
    try {
      const info = await client.describe(text);
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
  async function knobChanged(control) {
    clearTimeout(knobTimer);
    forwardKnob(ui.form, control);
    if (await formChanged()) startRun();
  }

  // An edit still being checked by the core must land before the run starts.
  async function runForm() {
    const fresh = composeScenario(ui.form, ui.preset.value) !== composed;
    if (!(await (fresh ? formChanged() : checking))) return;
    if (!ui.run.disabled) startRun();
  }

  function commitPreset() {
    presetPending = false;
    load(`v=1&preset=${ui.preset.value}`);
  }

  ui.preset.addEventListener('keydown', (e) => {
    presetByKeyboard = BROWSE.has(e.key) || e.key.length === 1;
    if (e.key === 'Enter' && presetPending) commitPreset();
  });
  ui.preset.addEventListener('pointerdown', () => {
    presetByKeyboard = false;
  });
  ui.preset.addEventListener('change', () => {
    presetPending = true;
    if (!presetByKeyboard) commitPreset();
  });
  ui.preset.addEventListener('blur', () => presetPending && commitPreset());
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
    clearTimeout(knobTimer);
    knobTimer = setTimeout(() => knobChanged(e.target), 800);
  });
  ui.run.addEventListener('click', runForm);

  const handlers = {
    ready({ presets: offered, nisBand }) {
      // A worker started after a crash is ready too: the presets are listed already, and the
      // scenario stays as it is unless none was loaded yet.
      if (!presets.length) {
        presets = offered;
        state.nisBand = nisBand;
        for (const p of presets)
          ui.preset.append(Object.assign(document.createElement('option'), { value: p.name, textContent: p.name }));
      }
      if (state.info === null) Promise.resolve(first()).then((text) => load(text));
    },
  };

  return { load, knob, handlers };
}
