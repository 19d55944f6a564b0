// The worker's pins: finished runs kept beside the current one (the core's Comparison), run in
// time slices like a run, and the overlay of one column across them.
import { Comparison, Simulation } from '../../pkg-run/imlab.js';
import { heldSim, held } from './run.js';
import { post, refuse, SLICE_MS, trapped, yieldToMessages } from './runtime.js';
import { refusal } from '../l10n/core-message.js';

/** @import * as P from './protocol.js' */

/** @type {Comparison | null} created with the run worker; a pool's worker holds no pins */
let comparison = null;

/** @type {{cancelled: boolean} | null} the pins being run */
let pinning = null;

/** Creates the pins' store (the run worker only). */
export function holdPins() {
  comparison = new Comparison();
}

/**
 * The pins' store. The page sends the pins' requests to the run worker only, which handles no
 * message before holdPins has created the store.
 */
const pins = () => /** @type {Comparison} */ (comparison);

/**
 * The pins message, naming each scenario refused or not run, and whether pinning was cancelled.
 * @param {P.PinRejected[]} rejected
 * @param {boolean} cancelled
 * @returns {P.Pins}
 */
function pinsMessage(rejected = [], cancelled = false) {
  const sim = heldSim();
  const legends = sim ? pins().legends(sim) : [];
  return { type: 'pins', scenarios: pins().scenarios(), legends, rejected, cancelled };
}

/**
 * Runs and pins `scenarios` one after the other, each in time slices like a run, with progress;
 * a 'pin-cancel' stops at the next slice and pins nothing more. Then the pins message.
 * @param {P.PinRequest} request
 */
export async function pinAll({ scenarios, column }) {
  const me = { cancelled: false };
  pinning = me;
  /** @type {P.PinRejected[]} */
  const rejected = [];
  for (const [index, scenario] of scenarios.entries()) {
    if (me.cancelled) {
      rejected.push({ scenario, cancelled: 'unrun' });
      continue;
    }
    let sim;
    try {
      pins().check_room();
      sim = new Simulation(scenario);
      sim.keep_column(column);
    } catch (e) {
      sim?.free();
      if (trapped(e)) return;
      rejected.push({ scenario, message: refusal(e) });
      continue;
    }
    while (!sim.finished) {
      try {
        sim.step_for(SLICE_MS);
      } catch (e) {
        if (trapped(e)) return;
        break; // a run that fails stays pinned with the samples before its failure
      }
      post({ type: 'pin-progress', index, count: scenarios.length, done: sim.done, total: sim.total });
      await yieldToMessages();
      if (me.cancelled) break;
    }
    if (me.cancelled) {
      sim.free();
      rejected.push({ scenario, cancelled: 'running' });
      continue;
    }
    try {
      pins().adopt(sim); // takes the run; `sim` is spent
    } catch (e) {
      if (trapped(e)) return;
      rejected.push({ scenario, message: refusal(e) });
    }
  }
  if (pinning === me) pinning = null;
  post(pinsMessage(rejected, me.cancelled));
}

export function cancelPins() {
  if (pinning) pinning.cancelled = true;
}

/** @param {P.UnpinRequest} request */
export function unpin({ index }) {
  pins().unpin(index);
  post(pinsMessage());
}

/** Unpins every run. */
export function unpinAll() {
  for (let i = pins().scenarios().length; i > 0; i--) pins().unpin(i - 1);
  post(pinsMessage());
}

/**
 * The overlay of the held run and the pins in one column.
 * @param {P.OverlayRequest} request
 */
export function overlay({ id, column, t0, t1, buckets }) {
  const me = held(id);
  if (!me) return;
  try {
    // The core's declaration types the envelopes loosely: each is a Float64Array.
    const data = [.../** @type {Float64Array[]} */ (pins().overlay(me.sim, column, t0, t1, buckets))];
    post(
      { type: 'overlay', id, column, data },
      null,
      data.map((a) => a.buffer),
    );
  } catch (e) {
    refuse(e, id);
  }
}
