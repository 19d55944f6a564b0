// The worker's run: the one simulation it holds, run in time slices with progress, and what the
// page asks of it once run (views, the CSV in chunks, a snapshot at one time, the predictors'
// comparison, a challenge's measures).
import { challenge_measure, Simulation, variant } from '../../pkg-run/imlab.js';
import { isCrashed, post, refuse, SLICE_MS, trapped, yieldToMessages } from './runtime.js';
import { refusal } from '../l10n/core-message.js';

/** @import * as P from './protocol.js' */
/** @import {Metrics} from '../../pkg-run/imlab.js' */

// Rows per CSV chunk, about 22 MB: neither the worker nor the page holds more than a chunk or two
// of a CSV that can reach 1.3 GB, past what one JS string can hold.
const CSV_ROWS = 20_000;

// Series that are not recorded columns: the bound (59), evaluated at the plot's times; the
// unknown terms d̃2, d̃4 of steps 2 and 4, evaluated from the simulated truth by a replay; and the
// residuals of the steps' designed dynamics under a scenario's own laws, and each step's error
// dynamics against its designed ones, by a replay too.
const BOUND = 'lyapunov_bound';
const DISTURBANCES = ['d2_tilde', 'd4_tilde'];
const RESIDUALS = ['law_r1', 'law_r2', 'law_r3', 'law_r4'];
const DESIGNED = ['zdot1', 'zdes1', 'zdot2', 'zdes2', 'zdot3', 'zdes3', 'zdot4', 'zdes4'];
/**
 * A set of replayed series: their names, and the core's method that gives them over [t0, t1] in
 * `buckets` buckets (an envelope [t, ...]).
 * @typedef {{names: string[], of: (sim: Simulation, t0: number, t1: number, buckets: number) => Float64Array[]}} Replayed
 */
/** @type {Replayed[]} the replayed series, each set with the core's method that gives it */
const REPLAYED = [
  { names: DISTURBANCES, of: (sim, t0, t1, b) => sim.disturbances(t0, t1, b) },
  { names: RESIDUALS, of: (sim, t0, t1, b) => sim.law_residuals(t0, t1, b) },
  { names: DESIGNED, of: (sim, t0, t1, b) => sim.designed_dynamics(t0, t1, b) },
];
const replayed = (/** @type {string[]} */ names) => REPLAYED.find((r) => names.some((c) => r.names.includes(c)));
const derived = (/** @type {string} */ c) => c === BOUND || REPLAYED.some((r) => r.names.includes(c));

/** @typedef {{id: number, sim: Simulation, cancelled: boolean}} Held */

/** @type {Held | null} */
let current = null;

/** @type {{serial: number, answer: (more: boolean) => void} | null} the CSV export waiting for the page's next request */
let exporting = null;

/**
 * The run the worker holds, when it is run `id` (else null).
 * @param {number} id
 */
export const held = (id) => (current?.id === id ? current : null);

/** The run the worker holds, whichever it is (the pins' legends name it). */
export const heldSim = () => current?.sim ?? null;

/**
 * The recorded columns of each plot, in the order of `groups`.
 * @param {P.Groups} groups
 */
const recordedColumns = (groups) =>
  Object.values(groups).map((names) =>
    // A plot of replayed series asks for the times alone, for when the core does not evaluate them.
    replayed(names) ? ['t'] : names.filter((c) => !derived(c)),
  );

/**
 * One view of the plots `groups`: a single pass of the core over the window (a replay, or the
 * overview the run kept when `groups` are the run's own and the window is the whole run).
 * @param {Held} run
 * @param {P.Groups} groups
 * @param {number} t0
 * @param {number} t1
 * @param {number} buckets
 * @returns {P.View}
 */
function view(run, groups, t0, t1, buckets) {
  const all = run.sim.view(recordedColumns(groups), t0, t1, buckets);
  /** @type {Record<string, P.PlotView>} */
  const plots = {};
  // Each replayed set is replayed once for all the plots that show part of it.
  /** @type {Map<Replayed, Float64Array[]>} */
  const replays = new Map();
  Object.entries(groups).forEach(([id, names], g) => {
    // A plot of replayed series shows them alone, on the times of their own envelope.
    const replay = replayed(names);
    if (replay) {
      if (!replays.has(replay)) {
        try {
          replays.set(replay, replay.of(run.sim, t0, t1, buckets));
        } catch (e) {
          if (trapped(e)) throw e;
          // Not evaluated for this scenario (d̃ with an observer with extra states or the delay
          // compensation, residuals without own laws, the designed dynamics for IFOC; the
          // walkthrough says so): no sample at the window's times.
          const t = all[g][0];
          replays.set(replay, [t, ...replay.names.map(() => new Float64Array(t.length).fill(NaN))]);
        }
      }
      // Copies: each plot's buffers are moved to the page on their own.
      const cols = /** @type {Float64Array[]} */ (replays.get(replay)).map((c) => c.slice());
      const asked = replay.names.filter((c) => names.includes(c));
      plots[id] = {
        t: cols[0],
        columns: Object.fromEntries(asked.map((c) => [c, cols[replay.names.indexOf(c) + 1]])),
      };
      return;
    }
    const cols = all[g];
    /** @type {Record<string, Float64Array>} */
    const columns = {};
    names
      .filter((c) => !derived(c))
      .forEach((name, i) => {
        columns[name] = cols[i + 1];
      });
    if (names.includes(BOUND)) columns[BOUND] = run.sim.lyapunov_bound(cols[0]);
    plots[id] = { t: cols[0], columns };
  });
  return { t0, t1, plots };
}

/**
 * Starts run `id`, ending the one held before; posts progress after each slice, then the run's
 * whole view and report.
 * @param {P.RunRequest} request
 */
export async function run({ id, scenario, groups, buckets, overlay }) {
  if (current) current.sim.free();
  current = null;
  let sim;
  try {
    sim = new Simulation(scenario);
  } catch (e) {
    refuse(e, id);
    return;
  }
  const me = { id, sim, cancelled: false };
  current = me;
  try {
    // The whole run's view is computed as it runs: the first plot needs no replay.
    sim.keep_overview(recordedColumns(groups), buckets);
    // With runs pinned, the overlay's column is kept as it runs: the overlay replays no run.
    if (overlay) sim.keep_column(overlay);
  } catch (e) {
    refuse(e, id);
    return;
  }
  let failure = null;
  let computeMs = 0;
  while (!sim.finished) {
    const start = performance.now();
    try {
      sim.step_for(SLICE_MS);
      computeMs += performance.now() - start;
    } catch (e) {
      if (trapped(e)) return;
      failure = refusal(e);
      break;
    }
    post({ type: 'progress', id, done: sim.done, total: sim.total });
    await yieldToMessages();
    if (current !== me) return; // superseded by a newer run, which freed this one
    if (me.cancelled) {
      post({ type: 'cancelled', id });
      return;
    }
  }
  const recorded = sim.rows > 0;
  const v = recorded ? view(me, groups, 0, Number.MAX_VALUE, buckets) : null;
  const stability = recorded ? (sim.stability() ?? null) : null;
  const report = recorded ? sim.report() : null;
  post(
    {
      type: 'done',
      id,
      rows: sim.rows,
      failure,
      view: v,
      computeMs,
      stability,
      figures: report?.figures ?? [],
      unreached: report?.unreached ?? [],
      transient: report?.transient ?? null,
      warnings: report?.warnings ?? [],
      peak_to_rated: report?.peak_to_rated ?? null,
      rms_to_rated: report?.rms_to_rated ?? null,
      nis_inside: report?.nis_inside ?? null,
    },
    v,
  );
}

/** @param {P.CancelRequest} request */
export function cancel({ id }) {
  const me = held(id);
  if (me) me.cancelled = true;
}

/**
 * A view of the held run's plots. A run that recorded nothing has no view to give (the page
 * keeps the previous plots).
 * @param {P.ViewRequest} request
 */
export function viewOf({ id, set, groups, t0, t1, buckets }) {
  const me = held(id);
  if (!me || me.sim.rows === 0) return;
  try {
    const v = view(me, groups, t0, t1, buckets);
    post({ type: 'view', id, set, view: v }, v);
  } catch (e) {
    refuse(e, id);
  }
}

/** @param {P.InspectRequest} request */
export function inspect({ id, t }) {
  const me = held(id);
  if (!me) return;
  try {
    post({ type: 'inspected', id, t, snapshot: me.sim.inspect(t) });
  } catch (e) {
    refuse(e, id);
  }
}

/**
 * The held run's measures for judging a challenge (null when it is no longer held).
 * @param {P.MeasureRequest} request
 */
export function measure({ id }) {
  try {
    const me = held(id);
    post({ type: 'challenge-measured', id, measures: me ? challenge_measure(me.sim) : null });
  } catch (e) {
    if (!trapped(e)) post({ type: 'challenge-measured', id, measures: null, error: refusal(e) });
  }
}

/**
 * Sends run `id` as CSV in chunks of rows. The page asks for each next chunk once it has stored
 * the last, so at most one is in transit; between chunks a cancel or a new run (which frees
 * this one) ends the export.
 * @param {P.CsvRequest} request
 */
export async function exportCsv({ id, serial }) {
  exporting?.answer(false); // one export at a time
  exporting = null;
  const me = held(id);
  if (!me) {
    post({ type: 'csv-failed', serial, message: null });
    return;
  }
  const total = me.sim.rows;
  for (let rows = 0; ;) {
    let bytes;
    try {
      bytes = me.sim.csv_chunk(rows, CSV_ROWS);
    } catch (e) {
      if (!trapped(e)) post({ type: 'csv-failed', serial, message: refusal(e) });
      return;
    }
    rows = Math.min(total, rows + CSV_ROWS);
    const wanted =
      rows < total &&
      new Promise((answer) => {
        exporting = { serial, answer };
      });
    post({ type: 'csv', serial, bytes, rows, total }, null, [bytes.buffer]);
    if (!wanted || !(await wanted) || current !== me) return;
  }
}

/**
 * The page's answer to a CSV chunk: the next one, or the end of the export.
 * @param {P.CsvNextRequest} request
 */
export function csvAnswer({ type, serial }) {
  if (exporting?.serial !== serial) return;
  exporting.answer(type === 'csv-next');
  exporting = null;
}

/**
 * Runs `scenario` to the end in slices, yielding between them; returns its metrics.
 * @param {string} scenario
 * @returns {Promise<Metrics | null>}
 */
async function runToEnd(scenario) {
  const sim = new Simulation(scenario);
  try {
    while (!sim.finished) {
      sim.step_for(SLICE_MS);
      await yieldToMessages();
    }
    return sim.metrics() ?? null;
  } catch (e) {
    trapped(e);
    throw e;
  } finally {
    if (!isCrashed()) sim.free();
  }
}

/**
 * The held run's scenario with each EKF predictor, run to the end.
 * @param {P.CompareRequest} request
 */
export async function compare({ id }) {
  const me = held(id);
  if (!me) return;
  // A run started while these two run frees the held one, so its scenario is read first.
  const scenario = me.sim.scenario;
  try {
    const results = [];
    for (const predictor of ['euler', 'rk4']) {
      const changed = variant(scenario, 'ekf', predictor);
      results.push({ predictor, scenario: changed, metrics: await runToEnd(changed) });
    }
    post({ type: 'compared', id, results });
  } catch (e) {
    if (!trapped(e)) post({ type: 'invalid', id, message: refusal(e), comparison: true });
  }
}

// V8 compiles each WASM function when it is first called, with its baseline compiler, and
// optimises functions that have run often. A short run in small chunks at start-up, read back as
// a finished run is (overview, view, stability, report), gets that done before the first real run.
export function warmUp() {
  const sim = new Simulation('v=1&preset=decay');
  sim.keep_overview([['omega']], 100);
  while (!sim.finished) sim.step_for(0);
  sim.view([['omega']], 0, Number.MAX_VALUE, 100);
  sim.stability();
  sim.report();
  sim.free();
}
