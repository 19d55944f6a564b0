// Module worker: owns the WASM core, runs simulations in time slices, answers view and export
// requests and runs stateless jobs. It moves messages only; every number comes from the core.
// What it is asked and what it answers is in protocol.js.
//
// The run worker holds one run (run.js) and the pins (pins.js). A pool's worker (`?role=pool`)
// answers jobs only (jobs.js): it holds no pins and skips the warm-up for a run's first slices.
import init, { describe, describe_form, nis_band, presets, recover } from '../../pkg-run/imlab.js';
import { cancelPins, holdPins, overlay, pinAll, unpin, unpinAll } from './pins.js';
import { cancel, compare, csvAnswer, exportCsv, inspect, measure, run, viewOf, warmUp } from './run.js';
import { addPanicSource, isCrashed, post, trapped } from './runtime.js';
import { TOOLS_WASM_URL, WASM_URL } from './wasm-url.js';
import { refusal } from '../l10n/core-message.js';

/** @import * as P from './protocol.js' */

const POOL = new URLSearchParams(self.location.search).get('role') === 'pool';

// Compiled while it streams in (the core's glue uses WebAssembly.instantiateStreaming).
const ready = init({ module_or_path: WASM_URL }).then(() => {
  if (!POOL) {
    holdPins();
    warmUp();
  }
  post({ type: 'ready', presets: presets(), nisBand: nis_band() });
});

/**
 * A scenario checked by the core ('recover' keeps the acceptable fields of a bad one and lists
 * the rejected ones, each with its key).
 * @param {P.DescribeRequest} request
 */
function describeScenario(request) {
  const { req } = request;
  try {
    const checked =
      request.type === 'describe-form'
        ? describe_form(request.form.preset, request.form.fields)
        : request.type === 'describe'
          ? describe(request.scenario)
          : recover(request.scenario);
    post({ type: 'described', req, checked });
  } catch (e) {
    if (!trapped(e)) post({ type: 'invalid', req, message: refusal(e) });
  }
}

/**
 * The jobs and the core built with its tools, fetched and compiled on the first job (the first
 * run needs neither); tried again on the next job should the fetch fail.
 * @type {Promise<typeof import('./jobs.js').JOBS> | null}
 */
let tools = null;
function loadTools() {
  tools ??= import('./jobs.js').then(
    async ({ JOBS, initTools, panic_message }) => {
      await initTools({ module_or_path: TOOLS_WASM_URL });
      addPanicSource(panic_message);
      return JOBS;
    },
    (e) => {
      tools = null;
      throw e;
    },
  );
  return tools;
}

/**
 * Job `kind` of `jobs` on its fields `d`.
 * @template {keyof P.RawJobs} K
 * @param {typeof import('./jobs.js').JOBS} jobs
 * @param {K} kind
 * @param {P.RawJobs[K]['req']} d
 * @returns {P.RawJobs[K]['result']}
 */
function runJob(jobs, kind, d) {
  const jobOf = jobs[kind];
  return jobOf(d);
}

/** @param {P.JobMessage} request */
async function job(request) {
  let jobs;
  try {
    jobs = await loadTools();
  } catch (e) {
    post({ type: 'job', job: request.job, error: refusal(e), unloaded: true });
    return;
  }
  if (isCrashed()) return;
  try {
    post({ type: 'job', job: request.job, result: runJob(jobs, request.kind, request) });
  } catch (e) {
    if (!trapped(e)) post({ type: 'job', job: request.job, error: refusal(e) });
  }
}

/** @param {MessageEvent<P.ToWorker>} event */
self.onmessage = async ({ data }) => {
  await ready;
  if (isCrashed()) return;
  switch (data.type) {
    case 'describe':
    case 'describe-form':
    case 'recover':
      return describeScenario(data);
    case 'run':
      return void run(data);
    case 'cancel':
      return cancel(data);
    case 'view':
      return viewOf(data);
    case 'inspect':
      return inspect(data);
    case 'compare':
      return void compare(data);
    case 'pin':
      return void pinAll(data);
    case 'pin-cancel':
      return cancelPins();
    case 'unpin':
      return unpin(data);
    case 'unpin-all':
      return unpinAll();
    case 'overlay':
      return overlay(data);
    case 'job':
      return void job(data);
    case 'challenge-measure':
      return measure(data);
    case 'csv':
      return void exportCsv(data);
    case 'csv-next':
    case 'csv-cancel':
      return csvAnswer(data);
    default:
      throw new Error(`unknown message type ${/** @type {{type: unknown}} */ (data).type}`);
  }
};
