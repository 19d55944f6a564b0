// Module worker: owns the WASM core, runs simulations in chunks, answers view and export requests.
// It moves messages only; every number comes from the Rust core.
//
// Protocol (page → worker):
//   {type: 'describe', req, scenario}          → {type: 'described', req, info} | {type: 'invalid', req, message}
//   {type: 'recover', req, scenario}           → {type: 'described', req, info: {...info, rejected}} | invalid
//     (keeps the acceptable fields of a bad scenario and lists the rejected ones)
//   {type: 'run', id, scenario, groups, buckets}
//        → {type: 'progress', id, done, total}* then
//          {type: 'done', id, view, rows, failure, computeMs, stability, figures, transient}
//          | {type: 'invalid', id, message} | {type: 'cancelled', id}
//   {type: 'cancel', id}
//   {type: 'view', id, t0, t1, buckets}        → {type: 'view', id, view}
//   {type: 'csv', id}                          → {type: 'csv', id, text}
//   {type: 'inspect', id, t}                   → {type: 'inspected', id, t, snapshot} | {type: 'invalid', id, message}
//   {type: 'compare', id, columns, buckets}    → {type: 'compared', id, results: [{predictor, metrics}]}
//   {type: 'pin', scenarios}                   → {type: 'pins', scenarios, legends} (runs and pins each)
//   {type: 'unpin', index}                     → {type: 'pins', scenarios, legends}
//   {type: 'overlay', id, column, t0, t1, buckets} → {type: 'overlay', id, column, data: [t, current, pins..., diffs...]}
//   {type: 'job', job, kind, ...}              → {type: 'job', job, result} | {type: 'job', job, error}
//     kinds: 'sweep' {scenario, changes, freq, amp, duration, offset}, 'seed' {scenario, seed, every},
//     'grid' {lo, hi, n}, 'bands' {runs}, 'summary' {points}, 'sweep-csv' {points}, 'seeds-csv' {results}
//     (stateless, so any worker of a pool can take any job)
// `groups` is {plotId: [column, ...]}: each plot gets its own M4 envelope (every point a recorded
// sample at its own time). A view is {t0, t1, plots: {plotId: {t, columns: {name: Float64Array}}}};
// its buffers are transferred, not copied. The column 'lyapunov_bound' is the bound (59)
// evaluated by the core at the plot's times.
import init, {
  Comparison, describe, inspect, log_grid, recover, nis_band, presets, seed_bands, seed_run, seeds_csv, Simulation, sweep_csv, sweep_point, sweep_summary, variant,
} from '../pkg/imlab.js';

const CHUNK_STEPS = 5_000; // 1–2 ms of work: cancel is honoured at once, and optimised code
// compiled in the background is picked up at the next chunk

let current = null; // {id, sim, groups, cancelled}
let comparison = null; // pinned runs, created with the module

const BOUND = 'lyapunov_bound';

function envelope(sim, names, t0, t1, buckets) {
  const recorded = names.filter((c) => c !== BOUND);
  const cols = sim.envelope(recorded, t0, t1, buckets);
  const columns = {};
  recorded.forEach((name, i) => {
    columns[name] = cols[i + 1];
  });
  if (names.includes(BOUND)) columns[BOUND] = sim.lyapunov_bound(cols[0]);
  return { t: cols[0], columns };
}

function view(run, t0, t1, buckets) {
  const plots = {};
  for (const [id, names] of Object.entries(run.groups)) plots[id] = envelope(run.sim, names, t0, t1, buckets);
  return { t0, t1, plots };
}

function post(message, view) {
  const transfer = view ? Object.values(view.plots).flatMap((p) => [p.t.buffer, ...Object.values(p.columns).map((a) => a.buffer)]) : [];
  self.postMessage(message, transfer);
}

// Lets queued messages (a cancel) run between chunks. A MessageChannel round trip is not
// clamped to 4 ms the way nested setTimeout(0) is.
const channel = new MessageChannel();
const waiting = [];
channel.port1.onmessage = () => waiting.shift()();
function yieldToMessages() {
  return new Promise((resolve) => {
    waiting.push(resolve);
    channel.port2.postMessage(null);
  });
}

async function run({ id, scenario, groups, buckets }) {
  if (current) current.sim.free();
  current = null;
  let sim;
  try {
    sim = new Simulation(scenario);
  } catch (e) {
    post({ type: 'invalid', id, message: String(e) });
    return;
  }
  const me = { id, sim, groups, cancelled: false };
  current = me;
  let failure = null;
  let computeMs = 0;
  while (!sim.finished) {
    const start = performance.now();
    try {
      sim.step(CHUNK_STEPS);
      computeMs += performance.now() - start;
    } catch (e) {
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
  const v = recorded ? view(me, 0, Number.MAX_VALUE, buckets) : null;
  const stability = recorded ? sim.stability() : null;
  const figures = recorded ? sim.figures() : [];
  const transient = recorded ? sim.transient() : null;
  post({ type: 'done', id, rows: sim.rows, failure, view: v, computeMs, stability, figures, transient }, v);
}

/** Runs `scenario` to the end in chunks, yielding between them; returns its metrics. */
async function runToEnd(scenario) {
  const sim = new Simulation(scenario);
  try {
    while (!sim.finished) {
      sim.step(CHUNK_STEPS);
      await yieldToMessages();
    }
    return sim.metrics();
  } finally {
    sim.free();
  }
}

async function compare({ id }) {
  try {
    const results = [];
    for (const predictor of ['euler', 'rk4']) {
      const scenario = variant(current.sim.scenario, 'ekf', predictor);
      results.push({ predictor, scenario, metrics: await runToEnd(scenario) });
    }
    post({ type: 'compared', id, results });
  } catch (e) {
    post({ type: 'invalid', id, message: `Comparison failed: ${e}` });
  }
}

// V8 first runs WASM in its baseline compiler and optimises functions that have run often.
// A short run in small chunks at start-up gets the closed loop optimised before the first
// real run.
function warmUp() {
  const sim = new Simulation('v=1&preset=decay');
  while (!sim.finished) sim.step(10);
  sim.free();
}

/** `scenario` with the field changes `[[key, value], ...]` applied by the core. */
function withChanges(scenario, changes) {
  return changes.reduce((s, [key, value]) => variant(s, key, value), scenario);
}

const JOBS = {
  grid: (d) => [...log_grid(d.lo, d.hi, d.n)],
  sweep: (d) => sweep_point(withChanges(d.scenario, d.changes), d.freq, d.amp, d.duration, d.offset),
  seed: (d) => seed_run(d.scenario, d.seed, d.every),
  bands: (d) => seed_bands(d.runs),
  summary: (d) => sweep_summary(d.points),
  'sweep-csv': (d) => sweep_csv(d.points),
  'seeds-csv': (d) => seeds_csv(d.results),
};

function pinsMessage() {
  return { type: 'pins', scenarios: comparison.scenarios(), legends: current ? comparison.legends(current.sim) : [] };
}

const ready = init().then(() => {
  comparison = new Comparison();
  warmUp();
  self.postMessage({ type: 'ready', presets: presets(), nisBand: nis_band() });
});

self.onmessage = async ({ data }) => {
  await ready;
  switch (data.type) {
    case 'describe':
      try {
        post({ type: 'described', req: data.req, info: describe(data.scenario) });
      } catch (e) {
        post({ type: 'invalid', req: data.req, message: String(e) });
      }
      break;
    case 'recover':
      try {
        const { encoded, rejected } = recover(data.scenario);
        post({ type: 'described', req: data.req, info: { ...describe(encoded), rejected } });
      } catch (e) {
        post({ type: 'invalid', req: data.req, message: String(e) });
      }
      break;
    case 'run':
      run(data);
      break;
    case 'cancel':
      if (current && current.id === data.id) current.cancelled = true;
      break;
    case 'view':
      if (current && current.id === data.id) {
        const v = view(current, data.t0, data.t1, data.buckets);
        post({ type: 'view', id: data.id, view: v }, v);
      }
      break;
    case 'inspect':
      if (current && current.id === data.id) {
        try {
          post({ type: 'inspected', id: data.id, t: data.t, snapshot: inspect(current.sim.scenario, data.t) });
        } catch (e) {
          post({ type: 'invalid', id: data.id, message: String(e) });
        }
      }
      break;
    case 'compare':
      if (current && current.id === data.id) compare(data);
      break;
    case 'pin':
      try {
        for (const s of data.scenarios) comparison.pin(s);
        post(pinsMessage());
      } catch (e) {
        post({ ...pinsMessage(), error: String(e) });
      }
      break;
    case 'unpin':
      comparison.unpin(data.index);
      post(pinsMessage());
      break;
    case 'overlay':
      if (current && current.id === data.id) {
        try {
          const data2 = [...comparison.overlay(current.sim, data.column, data.t0, data.t1, data.buckets)];
          self.postMessage({ type: 'overlay', id: data.id, column: data.column, data: data2 }, data2.map((a) => a.buffer));
        } catch (e) {
          post({ type: 'invalid', id: data.id, message: String(e) });
        }
      }
      break;
    case 'job':
      try {
        post({ type: 'job', job: data.job, result: JOBS[data.kind](data) });
      } catch (e) {
        post({ type: 'job', job: data.job, error: String(e) });
      }
      break;
    case 'csv':
      if (current && current.id === data.id) post({ type: 'csv', id: data.id, text: current.sim.csv() });
      break;
    default:
      throw new Error(`unknown message type ${data.type}`);
  }
};
