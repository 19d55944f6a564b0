// The scenario in the settings form: loading one (from the address, a preset, history or a
// lesson), checking each edit of the form or of a walkthrough knob with the core, the preset
// picker, and Run.
import { $, say, ui } from '../ui/page.js';
import { formScenario, forwardKnob, markInvalid, renderFields, syncFields } from './controls.js';
import { ScenarioRefused, WorkerFailed } from '../client/run-client.js';
import { designView } from './design-view.js';
import { DEFAULT_PRESET, DEFAULT_SCENARIO, scenarioFromUrl, showScenario } from '../ui/url.js';
import { listed } from '../ui/quote.js';
import { t } from '../l10n/l10n.js';
import { listPresets, pickPresets } from './preset-picker.js';
import { followKnobs, knobMaker } from './knobs.js';

/** @import * as P from '../worker/protocol.js' */
/** @import { State } from '../main.js' */
/** @import { RunClient } from '../client/run-client.js' */
/** @import { Walkthrough } from '../teaching/walkthrough.js' */
/** @import { Control } from './knobs.js' */

/**
 * The fields the form shows for description `info`, and whether each acts: what its build follows.
 * @param {P.Info | null} info
 */
const shownFields = (info) =>
  info?.fields
    .filter((f) => f.value !== null)
    .map((f) => `${f.key}${f.acts ? '' : '-'}`)
    .join();

/**
 * The core's description of `text`, else of its valid fields, else of the default; says which
 * (`state.notice` when all of it is valid).
 * @param {RunClient} client
 * @param {State} state
 * @param {string} text
 * @returns {Promise<P.Info>}
 */
async function describeLoaded(client, state, text) {
  try {
    const info = await client.describe(text);
    say(state.notice ?? '', 'info');
    return info;
  } catch (e) {
    if (e instanceof WorkerFailed) throw e;
    // Keep what is valid; name every field that was left out.
    const { info, rejected } = await client.recover(text).catch((again) => {
      if (again instanceof WorkerFailed) throw again;
      return { info: null, rejected: [] };
    });
    if (info !== null) {
      say(
        t('settings-link-rejected', {
          list: listed(
            rejected.map((r) => r.message),
            '; ',
          ),
        }),
      );
      return info;
    }
    say(t('settings-link-refused', { reason: /** @type {Error} */ (e).message, preset: DEFAULT_PRESET }));
    return client.describe(DEFAULT_SCENARIO);
  }
}

/**
 * The first scenario's loader: it loads the scenario `first()` resolves with (null when it has
 * loaded one itself: a lesson's run), once a worker, unless one is loaded. Asked as the page
 * starts, its description waits in the worker's queue behind the core's loading and comes just
 * after `ready` (the worker answers in order); `again()` lets a worker restarted after a crash ask
 * once more.
 * @param {State} state
 * @param {() => string | null | Promise<string>} first
 * @param {(text: string) => Promise<void>} load
 */
function firstLoader(state, first, load) {
  let asked = false;
  const loadFirst = () => {
    if (state.info !== null || asked) return;
    asked = true;
    Promise.resolve(first()).then((text) => (text === null ? undefined : load(text)));
  };
  loadFirst.again = () => {
    asked = false;
  };
  return loadFirst;
}

/**
 * Has Enter in a settings field, and a submission of the form, call `runForm()` (a form of many
 * fields and no submit button has no implicit submission, so Enter is taken here).
 * @param {() => unknown} runForm
 */
function runOnSubmit(runForm) {
  ui.form.addEventListener('keydown', (e) => {
    if (e.key !== 'Enter' || !(e.target instanceof Element && e.target.matches('input, select'))) return;
    e.preventDefault();
    runForm();
  });
  ui.form.addEventListener('submit', (e) => {
    e.preventDefault();
    runForm();
  });
}

/**
 * The settings; `startRun()` and `markUnrun(unrun)` are the run's, `openSettings(open)` opens the
 * settings drawer. The worker's `ready` message (`handlers`) lists the presets and loads the
 * scenario `first()` resolves with (the address's, unless a challenge gives it). `described(info)`
 * follows every description the form takes; `mayRun(info)` is asked before every run (an open
 * challenge refuses a value outside its ranges): `true` at once when nothing needs asking, else a
 * promise of the answer.
 * @param {{client: RunClient, state: State, walkthrough: Walkthrough, startRun: () => void,
 *   markUnrun: (unrun: boolean) => void, openSettings: (open: boolean) => void,
 *   first?: () => string | null | Promise<string>, described?: (info: P.Info) => void,
 *   mayRun?: (info: P.Info) => true | Promise<boolean>}} parts
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
  mayRun = () => true,
}) {
  /** @type {P.Spoken<P.Ready>['presets']} */
  let presets = []; // the core's presets: {name, description}
  // Starts the run of the form's scenario, unless `mayRun` refuses it (it says why); resolves with
  // whether it started. It is asked only once the core has accepted the form's scenario, whose
  // description the page then holds.
  const startChecked = async () => {
    const allowed = await mayRun(/** @type {P.Info} */ (state.info));
    if (allowed) startRun();
    return allowed;
  };
  /** @type {string | null} */
  let composed = null; // the scenario the form held when last checked
  let checking = Promise.resolve(true); // that check: whether the core accepted it
  const knobs = knobMaker(state); // the walkthrough's knobs, with unique ids
  const showDesign = designView(client, ui.designDoc); // the derived design, when the scenario has it

  /**
   * Shows `info` in the form, which showed `before` (re-built only where its fields differ).
   * @param {P.Info} info
   * @param {P.Info | null} [before]
   */
  function applyDescription(info, before = state.info) {
    const presetChanged = ui.preset.value !== info.preset;
    state.info = info;
    knobs.reset();
    if (shownFields(before) !== shownFields(info) || presetChanged) renderFields(ui.form, info);
    else syncFields(ui.form, info);
    walkthrough.describe(info);
    ui.preset.value = info.preset;
    // The preset's description, and what this run changes of it (a lesson's run may hold another
    // speed or length than the preset says).
    const description = presets.find((p) => p.name === ui.preset.value)?.description ?? '';
    // A changed run is not the preset's: what the description says of the preset's run (its
    // speed, its outcome) need not hold for it, and the page says so.
    const changed = info.changed.length
      ? t('settings-preset-changed', { preset: ui.preset.value, description, fields: info.changed.join(', ') })
      : description;
    // A setting the run ignores is said, never left to look as if it acted.
    ui.presetDoc.textContent = info.idle.length
      ? t('settings-idle', { changed, idle: info.idle.join(t('settings-idle-separator')) })
      : changed;
    void showDesign(info);
    ui.run.disabled = state.running;
    markInvalid(ui.form, null);
    described(info);
  }

  /**
   * Loads a scenario string (from the URL, a preset or history); a bad one keeps its valid fields.
   * @param {string} text
   */
  async function load(text) {
    /** @type {P.Info} */
    let info;
    try {
      info = await describeLoaded(client, state, text);
    } catch (e) {
      if (e instanceof WorkerFailed) return;
      throw e;
    }
    showScenario(info.encoded);
    checking = Promise.resolve(true); // the form now holds this valid scenario
    const allowed = mayRun(info);
    if (allowed === true) {
      // Nothing to ask: the run starts first, and the form is built while the worker computes.
      const before = state.info;
      state.info = info;
      startRun();
      applyDescription(info, before);
    } else {
      applyDescription(info);
      if (await allowed) startRun();
    }
  }

  /** Checks the form's scenario with the core; resolves with whether it is valid. An invalid value
   * is marked at its field, and at the walkthrough knob when a knob was edited. */
  function formChanged() {
    checking = checkForm();
    return checking;
  }

  async function checkForm() {
    const form = formScenario(ui.form, ui.preset.value);
    composed = JSON.stringify(form);
    try {
      const info = await client.describeForm(form);
      applyDescription(info);
      // The address keeps describing the run on screen until these settings run.
      markUnrun(info.encoded !== state.ranScenario);
      walkthrough.markKnob(null);
      say('');
      return true;
    } catch (e) {
      if (e instanceof WorkerFailed) return false;
      const key = e instanceof ScenarioRefused ? e.key : null;
      markUnrun(true);
      markInvalid(ui.form, key);
      // The field must be visible to be fixed: open the drawer where the settings live in one.
      if (ui.form.offsetParent === null && ui.form.querySelector('.invalid')) openSettings(true);
      const { message } = /** @type {Error} */ (e);
      walkthrough.markKnob(key, message);
      ui.run.disabled = true;
      say(message);
      return false;
    }
  }

  /**
   * A walkthrough knob was edited: check it and re-run, so its section's plots follow.
   * @param {Control} control
   */
  async function knobChanged(control) {
    forwardKnob(ui.form, control);
    if (await formChanged()) await startChecked();
  }

  // An edit still being checked by the core must land before the run starts.
  async function runForm() {
    const fresh = JSON.stringify(formScenario(ui.form, ui.preset.value)) !== composed;
    if (!(await (fresh ? formChanged() : checking))) return;
    if (!ui.run.disabled) await startChecked();
  }

  /**
   * Makes the form's scenario the run on screen before an analysis runs it, so that the plots, the
   * address and the analysis are of one scenario: waits for the check of the form's last edit and
   * starts its run unless it is the run on screen already. Resolves with whether the form's
   * scenario is valid and may run (the message line says why not).
   */
  async function runCurrent() {
    if (!(await checking) || state.info === null) return false;
    return state.info.encoded === state.ranScenario || startChecked();
  }

  pickPresets(ui.preset, (name) => load(`v=1&preset=${name}`));
  ui.form.addEventListener('change', formChanged);
  runOnSubmit(runForm);
  // A walkthrough knob re-runs on change, on Enter, or after a pause in typing.
  followKnobs($('walkthrough'), knobChanged);
  ui.run.addEventListener('click', runForm);

  const loadFirst = firstLoader(state, first, load);

  /** @type {P.Handlers} */
  const handlers = {
    ready({ presets: offered, nisBand }) {
      // A worker started after a crash is ready too: the presets are listed already, and the
      // scenario stays as it is unless none was loaded yet.
      if (!presets.length) {
        presets = offered;
        // The core's band, [low, high].
        state.nisBand = [nisBand[0], nisBand[1]];
        listPresets(ui.preset, presets);
      } else loadFirst.again();
      loadFirst();
    },
  };

  return { load, loadFirst, runCurrent, knob: knobs.knob, handlers };
}
