// Module worker: owns the WASM core, runs simulations in chunks, answers view and export requests.
// It moves messages only; every number comes from the Rust core.
//
// Protocol (page → worker):
//   {type: 'describe', req, scenario}          → {type: 'described', req, info} | {type: 'invalid', req, message}
//   {type: 'recover', req, scenario}           → {type: 'described', req, info: {...info, rejected}} | invalid
//     (keeps the acceptable fields of a bad scenario and lists the rejected ones)
//   {type: 'run', id, scenario, groups, buckets, overlay}
//        → {type: 'progress', id, done, total}* then
//          {type: 'done', id, view, rows, failure, computeMs, stability, figures, unreached, transient, warnings}
//          | {type: 'invalid', id, message} | {type: 'cancelled', id}
//     (`view` is the whole run's view of `groups`, kept while the run went; `overlay`, a column
//     or null, is kept as it goes for the overlay with the pins)
//   {type: 'cancel', id}
//   {type: 'view', id, set, groups, t0, t1, buckets} → {type: 'view', id, set, view}
//     (`set` names the page's plot set the view is for, and comes back as given)
//   {type: 'csv', id, serial}                  → {type: 'csv', serial, bytes, rows, total}, one a chunk
//     of rows (bytes a transferred Uint8Array; the chunks concatenate to the CSV; the last has
//     rows === total) | {type: 'csv-failed', serial, message}
//   {type: 'csv-next', serial}                 asks for the next chunk once the page has stored one
//   {type: 'csv-cancel', serial}               ends the export (a new run ends it too)
//   {type: 'inspect', id, t}                   → {type: 'inspected', id, t, snapshot} | {type: 'invalid', id, message}
//   {type: 'compare', id, columns, buckets}    → {type: 'compared', id, results: [{predictor, metrics}]}
//   {type: 'pin', scenarios, column}           → {type: 'pin-progress', index, count, done, total}* then
//          {type: 'pins', scenarios, legends, rejected: [{scenario, message}]}
//     (runs each in time slices and pins it, keeping the overlay's `column`; `rejected` lists those
//     the core refused and those a cancel left unrun)
//   {type: 'pin-cancel'}                       stops the pins being run at the next slice
//   {type: 'unpin', index}                     → {type: 'pins', scenarios, legends, rejected: []}
//   {type: 'overlay', id, column, t0, t1, buckets} → {type: 'overlay', id, column, data: [t, current, pins..., diffs...]}
//     (every run keeps `column` from then on: the next overlay of it replays none)
//   {type: 'job', job, kind, ...}              → {type: 'job', job, result} | {type: 'job', job, error}
//     kinds: 'sweep' {scenario, changes, freq, amp, duration, offset}, 'seed' {scenario, seed, every},
//     'grid' {lo, hi, n}, 'seed-range' {first, n}, 'bands' {runs}, 'summary' {points},
//     'sweep-csv' {points}, 'seeds-csv' {results}; the model-error map's 'map-plan' {scenario, text}
//     → {map, figures}, 'map-run' {scenario, seed} (one cell, one seed), 'map-cells' {map, runs}
//     (runs cell after cell) → cells, 'map-csv' {map, cells}
//     (stateless, so any worker of a pool can take any job), and the challenge jobs of
//     challenge-jobs.js
//   {type: 'challenge-measure', id}         → {type: 'challenge-measured', id, measures}: run `id`'s
//     measures for judging a challenge (when the run is no longer held, measures is null)
// Unprompted: {type: 'ready', presets, nisBand} once the core is loaded, and {type: 'crashed', message}
// when the core trapped (a panic or running out of memory) or the worker hit an uncaught error:
// the WASM instance may be unusable then, so the worker never calls it again and the page
// replaces the worker.
// `groups` is {plotId: [column, ...]}: each plot gets its own M4 envelope (every point a recorded
// sample at its own time). A view is {t0, t1, plots: {plotId: {t, columns: {name: Float64Array}}}};
// its buffers are transferred, not copied. The column 'lyapunov_bound' is the bound (59)
// evaluated by the core at the plot's times.
import init, {
  challenge_measure,
  Comparison,
  describe,
  log_grid,
  nis_band,
  panic_message,
  presets,
  recover,
  robust_cells,
  robust_csv,
  robust_figures,
  robust_plan,
  robust_run,
  seed_bands,
  seed_range,
  seed_run,
  seeds_csv,
  Simulation,
  sweep_csv,
  sweep_point,
  sweep_summary,
  variant,
} from '../../pkg/imlab.js';
import { CHALLENGE_JOBS } from './challenge-jobs.js';

// A slice of work between two looks at the message queue (ms of the worker's clock, read by the
// core): Cancel is honoured within it, and optimised code compiled in the background is picked
// up at the next slice. Bounded by time, as one sample can cost a thousand ordinary ones.
const SLICE_MS = 4;

// Rows per CSV chunk, about 22 MB: neither the worker nor the page holds more than a chunk or two
// of a CSV that can reach 1.3 GB, past what one JS string can hold.
const CSV_ROWS = 20_000;

let current = null; // {id, sim, cancelled}
let comparison = null; // pinned runs, created with the module
let exporting = null; // {serial, answer}: the CSV export waiting for the page's next request
let pinning = null; // {cancelled}: the pins being run
let crashed = false;

const BOUND = 'lyapunov_bound';

/**
 * Reports a crash to the page once: `error` is a trap or an error nothing caught. A trap can
 * leave the instance half-way through a call (a borrow held, memory exhausted), so from here on
 * nothing calls the core: messages are ignored and no awaited yield resumes.
 */
function crash(error) {
  if (crashed) return;
  crashed = true;
  current = null;
  let panic;
  try {
    panic = panic_message();
  } catch {
    // The instance is too broken to read the message; the trap's own text still tells.
  }
  let message = error instanceof Error ? `${error.name}: ${error.message}` : String(error);
  // A Rust allocation failure aborts without a panic, as an 'unreachable' trap.
  if (panic) message += `; Rust panic: ${panic}`;
  else if (error instanceof WebAssembly.RuntimeError && /unreachable/.test(error.message))
    message += '; most likely the core ran out of memory';
  self.postMessage({ type: 'crashed', message });
}

/** Reports `e` as a crash when it is a trap (not a clean error thrown by the core); returns whether it was. */
function trapped(e) {
  if (!(e instanceof WebAssembly.RuntimeError)) return false;
  crash(e);
  return true;
}

self.addEventListener('unhandledrejection', (e) => {
  e.preventDefault();
  crash(e.reason);
});
self.addEventListener('error', (e) => {
  e.preventDefault();
  crash(e.error ?? e.message);
});

/** The recorded columns of each plot, in the order of `groups` ({plotId: [column, ...]}). */
const recordedColumns = (groups) => Object.values(groups).map((names) => names.filter((c) => c !== BOUND));

/**
 * One view of the plots `groups`: a single pass of the core over the window (a replay, or the
 * overview the run kept when `groups` are the run's own and the window is the whole run).
 */
function view(run, groups, t0, t1, buckets) {
  const all = run.sim.view(recordedColumns(groups), t0, t1, buckets);
  const plots = {};
  Object.entries(groups).forEach(([id, names], g) => {
    const cols = all[g];
    const columns = {};
    names
      .filter((c) => c !== BOUND)
      .forEach((name, i) => {
        columns[name] = cols[i + 1];
      });
    if (names.includes(BOUND)) columns[BOUND] = run.sim.lyapunov_bound(cols[0]);
    plots[id] = { t: cols[0], columns };
  });
  return { t0, t1, plots };
}

function post(message, view) {
  const transfer = view
    ? Object.values(view.plots).flatMap((p) => [p.t.buffer, ...Object.values(p.columns).map((a) => a.buffer)])
    : [];
  self.postMessage(message, transfer);
}

// Lets queued messages (a cancel) run between chunks. A MessageChannel round trip is not
// clamped to 4 ms the way nested setTimeout(0) is. After a crash no yield resumes, so no loop
// goes on calling the core.
const channel = new MessageChannel();
const waiting = [];
channel.port1.onmessage = () => {
  const resume = waiting.shift();
  if (!crashed) resume();
};
function yieldToMessages() {
  return new Promise((resolve) => {
    waiting.push(resolve);
    channel.port2.postMessage(null);
  });
}

async function run({ id, scenario, groups, buckets, overlay }) {
  if (current) current.sim.free();
  current = null;
  let sim;
  try {
    sim = new Simulation(scenario);
  } catch (e) {
    if (!trapped(e)) post({ type: 'invalid', id, message: String(e) });
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
    if (!trapped(e)) post({ type: 'invalid', id, message: String(e) });
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
      failure = String(e);
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
  const stability = recorded ? sim.stability() : null;
  const report = recorded ? sim.report() : null;
  const figures = report?.figures ?? [];
  const transient = report?.transient ?? null;
  const warnings = report?.warnings ?? [];
  const unreached = report?.unreached ?? [];
  post(
    {
      type: 'done',
      id,
      rows: sim.rows,
      failure,
      view: v,
      computeMs,
      stability,
      figures,
      unreached,
      transient,
      warnings,
    },
    v,
  );
}

/**
 * Sends run `id` as CSV in chunks of rows. The page asks for each next chunk once it has stored
 * the last, so at most one is in transit; between chunks a cancel or a new run (which frees
 * this one) ends the export.
 */
async function exportCsv({ id, serial }) {
  exporting?.answer(false); // one export at a time
  exporting = null;
  const me = current;
  if (me?.id !== id) {
    post({ type: 'csv-failed', serial, message: 'this run is no longer held by the worker; run it again' });
    return;
  }
  const total = me.sim.rows;
  for (let rows = 0; ;) {
    let bytes;
    try {
      bytes = me.sim.csv_chunk(rows, CSV_ROWS);
    } catch (e) {
      if (!trapped(e)) post({ type: 'csv-failed', serial, message: String(e) });
      return;
    }
    rows = Math.min(total, rows + CSV_ROWS);
    const wanted =
      rows < total &&
      new Promise((answer) => {
        exporting = { serial, answer };
      });
    self.postMessage({ type: 'csv', serial, bytes, rows, total }, [bytes.buffer]);
    if (!wanted || !(await wanted) || current !== me) return;
  }
}

/** Runs `scenario` to the end in chunks, yielding between them; returns its metrics. */
async function runToEnd(scenario) {
  const sim = new Simulation(scenario);
  try {
    while (!sim.finished) {
      sim.step_for(SLICE_MS);
      await yieldToMessages();
    }
    return sim.metrics();
  } catch (e) {
    trapped(e);
    throw e;
  } finally {
    if (!crashed) sim.free();
  }
}

async function compare({ id }) {
  // A run started while these two run frees current.sim, so its scenario is read first.
  const scenario = current.sim.scenario;
  try {
    const results = [];
    for (const predictor of ['euler', 'rk4']) {
      const changed = variant(scenario, 'ekf', predictor);
      results.push({ predictor, scenario: changed, metrics: await runToEnd(changed) });
    }
    post({ type: 'compared', id, results });
  } catch (e) {
    if (!trapped(e)) post({ type: 'invalid', id, message: `Comparison failed: ${e}` });
  }
}

// V8 compiles each WASM function when it is first called, with its baseline compiler, and
// optimises functions that have run often. A short run in small chunks at start-up, read back as
// a finished run is (overview, view, stability, report), gets that done before the first real run.
function warmUp() {
  const sim = new Simulation('v=1&preset=decay');
  sim.keep_overview([['omega']], 100);
  while (!sim.finished) sim.step_for(0);
  sim.view([['omega']], 0, Number.MAX_VALUE, 100);
  sim.stability();
  sim.report();
  sim.free();
}

/**
 * Runs and pins `scenarios` one after the other, each in time slices like a run, with progress
 * ({type: 'pin-progress', index, count, done, total}); a 'pin-cancel' stops at the next slice and
 * pins nothing more. Then the pins message, naming each scenario refused or not run.
 */
async function pinAll({ scenarios, column }) {
  const me = { cancelled: false };
  pinning = me;
  const rejected = [];
  for (const [index, scenario] of scenarios.entries()) {
    if (me.cancelled) {
      rejected.push({ scenario, message: 'not run: pinning was cancelled' });
      continue;
    }
    let sim;
    try {
      comparison.check_room();
      sim = new Simulation(scenario);
      sim.keep_column(column);
    } catch (e) {
      sim?.free();
      if (trapped(e)) return;
      rejected.push({ scenario, message: String(e) });
      continue;
    }
    while (!sim.finished) {
      try {
        sim.step_for(SLICE_MS);
      } catch (e) {
        if (trapped(e)) return;
        break; // a run that fails stays pinned with the samples before its failure
      }
      self.postMessage({ type: 'pin-progress', index, count: scenarios.length, done: sim.done, total: sim.total });
      await yieldToMessages();
      if (me.cancelled) break;
    }
    if (me.cancelled) {
      sim.free();
      rejected.push({ scenario, message: 'cancelled' });
      continue;
    }
    try {
      comparison.adopt(sim); // takes the run; `sim` is spent
    } catch (e) {
      if (trapped(e)) return;
      rejected.push({ scenario, message: String(e) });
    }
  }
  if (pinning === me) pinning = null;
  post(pinsMessage(rejected));
}

/** `scenario` with the field changes `[[key, value], ...]` applied by the core. */
function withChanges(scenario, changes) {
  return changes.reduce((s, [key, value]) => variant(s, key, value), scenario);
}

const JOBS = {
  grid: (d) => [...log_grid(d.lo, d.hi, d.n)],
  sweep: (d) => sweep_point(withChanges(d.scenario, d.changes), d.freq, d.amp, d.duration, d.offset),
  'seed-range': (d) => [...seed_range(d.first, d.n)],
  seed: (d) => seed_run(d.scenario, d.seed, d.every),
  bands: (d) => seed_bands(d.runs),
  summary: (d) => sweep_summary(d.points),
  'sweep-csv': (d) => sweep_csv(d.points),
  'seeds-csv': (d) => seeds_csv(d.results),
  'map-plan': (d) => ({ map: robust_plan(d.scenario, d.text), figures: robust_figures() }),
  'map-run': (d) => robust_run(d.scenario, d.seed),
  'map-cells': (d) => robust_cells(d.map, d.runs),
  'map-csv': (d) => robust_csv(d.map, d.cells),
  ...CHALLENGE_JOBS,
};

function pinsMessage(rejected = []) {
  return {
    type: 'pins',
    scenarios: comparison.scenarios(),
    legends: current ? comparison.legends(current.sim) : [],
    rejected,
  };
}

// A pool's worker (`?role=pool`) answers stateless jobs only: it holds no pins and needs no
// warm-up for the run's first slices.
const POOL = new URLSearchParams(self.location.search).get('role') === 'pool';

const ready = init().then(() => {
  if (!POOL) {
    comparison = new Comparison();
    warmUp();
  }
  self.postMessage({ type: 'ready', presets: presets(), nisBand: nis_band() });
});

self.onmessage = async ({ data }) => {
  await ready;
  if (crashed) return;
  switch (data.type) {
    case 'describe':
      try {
        post({ type: 'described', req: data.req, info: describe(data.scenario) });
      } catch (e) {
        if (!trapped(e)) post({ type: 'invalid', req: data.req, message: String(e) });
      }
      break;
    case 'recover':
      try {
        const { encoded, rejected } = recover(data.scenario);
        post({ type: 'described', req: data.req, info: { ...describe(encoded), rejected } });
      } catch (e) {
        if (!trapped(e)) post({ type: 'invalid', req: data.req, message: String(e) });
      }
      break;
    case 'run':
      run(data);
      break;
    case 'cancel':
      if (current && current.id === data.id) current.cancelled = true;
      break;
    case 'view':
      // A run that recorded nothing has no view to give (the page keeps the previous plots).
      if (current && current.id === data.id && current.sim.rows > 0) {
        try {
          const v = view(current, data.groups, data.t0, data.t1, data.buckets);
          post({ type: 'view', id: data.id, set: data.set, view: v }, v);
        } catch (e) {
          if (!trapped(e)) post({ type: 'invalid', id: data.id, message: String(e) });
        }
      }
      break;
    case 'inspect':
      if (current && current.id === data.id) {
        try {
          post({ type: 'inspected', id: data.id, t: data.t, snapshot: current.sim.inspect(data.t) });
        } catch (e) {
          if (!trapped(e)) post({ type: 'invalid', id: data.id, message: String(e) });
        }
      }
      break;
    case 'compare':
      if (current && current.id === data.id) compare(data);
      break;
    case 'pin':
      pinAll(data);
      break;
    case 'pin-cancel':
      if (pinning) pinning.cancelled = true;
      break;
    case 'unpin':
      comparison.unpin(data.index);
      post(pinsMessage());
      break;
    case 'overlay':
      if (current && current.id === data.id) {
        try {
          const data2 = [...comparison.overlay(current.sim, data.column, data.t0, data.t1, data.buckets)];
          self.postMessage(
            { type: 'overlay', id: data.id, column: data.column, data: data2 },
            data2.map((a) => a.buffer),
          );
        } catch (e) {
          if (!trapped(e)) post({ type: 'invalid', id: data.id, message: String(e) });
        }
      }
      break;
    case 'job':
      try {
        post({ type: 'job', job: data.job, result: JOBS[data.kind](data) });
      } catch (e) {
        if (!trapped(e)) post({ type: 'job', job: data.job, error: String(e) });
      }
      break;
    case 'challenge-measure':
      try {
        const held = current && current.id === data.id;
        post({ type: 'challenge-measured', id: data.id, measures: held ? challenge_measure(current.sim) : null });
      } catch (e) {
        if (!trapped(e)) post({ type: 'challenge-measured', id: data.id, measures: null, error: String(e) });
      }
      break;
    case 'csv':
      exportCsv(data);
      break;
    case 'csv-next':
    case 'csv-cancel':
      if (exporting?.serial === data.serial) {
        exporting.answer(data.type === 'csv-next');
        exporting = null;
      }
      break;
    default:
      throw new Error(`unknown message type ${data.type}`);
  }
};
