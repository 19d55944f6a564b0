// The run client: the simulation worker, which owns the core, and the page's messages with it.
// Describe requests, jobs and challenge measures are answered as promises; every other message
// goes to the page's handler of its type. A worker that fails is replaced.
import { WORKER_URL } from '../worker-url.js';
import { crashReason, errorReason, jobError, unreadable, watch } from './watch.js';
import { loadRest, spoken } from '../l10n/l10n.js';

/** @import * as P from '../worker/protocol.js' */

/**
 * A request awaiting its answer. `resolve` takes the answer of the request's own type (ask's
 * `T`): it is declared as a method, so that each request's own `resolve` can be kept here.
 * @typedef {{resolve(answer: unknown): void, reject: (error: Error) => void}} Pending
 */

/** A request the worker could not answer because it failed; the page has said so already. */
export class WorkerFailed extends Error {}

/** A scenario the core refused: its message, and the key of the field at fault (or null). */
export class ScenarioRefused extends Error {
  /** @param {P.Checked['rejected'][number]} rejected */
  constructor({ key, message }) {
    super(message);
    this.key = key;
  }
}

/**
 * The description of a checked scenario, or a ScenarioRefused naming the field at fault.
 * @param {P.Checked} checked
 */
function described({ info, rejected }) {
  if (info === null) throw new ScenarioRefused(rejected[0]);
  return info;
}

export class RunClient {
  /**
   * `onFailed(reason, restarting)` tells the page that the worker failed; `restarting` is false
   * when it never started, which a restart would only repeat.
   * @param {(reason: string, restarting: boolean) => void} onFailed
   */
  constructor(onFailed) {
    this.onFailed = onFailed;
    /** @type {P.Handlers} the page's handlers of the worker's messages, by type */
    this.handlers = {};
    /** @type {Worker | null} the current worker, from start() on */
    this.worker = null;
    this.ready = false; // whether the current worker has loaded the core
    this.req = 0;
    /** @type {Map<string, Pending>} requests awaiting their answer, by key */
    this.pending = new Map();
    this.failures = 0; // workers failed so far
  }

  /** Starts the worker: the first time, the one boot.js started with the page, if there is one. */
  start() {
    this.ready = false;
    const boot = globalThis.imlabBoot;
    globalThis.imlabBoot = null; // boot.js, if it comes later, starts none
    if (!boot) {
      this.worker = new Worker(WORKER_URL, { type: 'module' });
      this.listen();
      return;
    }
    // Until the page is wired (the rest of main.js), boot.js keeps what the worker says; then it
    // is taken in order, each message on its own, and the worker's failure meanwhile last. A
    // failure while it is taken ends the worker, and what it said after that is dropped.
    this.worker = boot.worker;
    queueMicrotask(() => {
      this.listen();
      const failures = this.failures;
      for (const data of boot.early) {
        if (this.failures !== failures) return;
        try {
          if (data.type === 'crashed') this.fail(crashReason(data));
          else this.receive(spoken(data));
        } catch (e) {
          reportError(e);
        }
      }
      const { failure } = boot;
      if (failure && this.failures === failures)
        this.fail(failure.unreadable ? unreadable() : errorReason(failure.message));
    });
  }

  listen() {
    watch(/** @type {Worker} */ (this.worker), {
      onMessage: (data) => this.receive(data),
      onFail: (reason) => this.fail(reason),
    });
  }

  /** @param {P.ToWorker} message */
  post(message) {
    /** @type {Worker} */ (this.worker).postMessage(message);
  }

  /**
   * The core's description of a scenario string; rejects with a ScenarioRefused, which names the
   * field at fault, when the core refuses it.
   * @param {string} scenario
   * @returns {Promise<P.Info>}
   */
  async describe(scenario) {
    return described(await this.check({ type: 'describe', req: ++this.req, scenario }));
  }

  /**
   * The core's description of a form's scenario, which the core writes from its parts; rejects
   * as describe() does.
   * @param {P.FormScenario} form
   * @returns {Promise<P.Info>}
   */
  async describeForm(form) {
    return described(await this.check({ type: 'describe-form', req: ++this.req, form }));
  }

  /**
   * The core's description of what can be kept of a scenario string (null when nothing can: a
   * bad `v` or `preset`), and every field it left out.
   * @param {string} scenario
   */
  recover(scenario) {
    return this.check({ type: 'recover', req: ++this.req, scenario });
  }

  /**
   * @param {P.DescribeRequest} request
   * @returns {Promise<P.Checked>}
   */
  check(request) {
    return this.ask(`describe ${request.req}`, request);
  }

  /**
   * Sends `message` and resolves with the answer that carries `key` (see receive).
   * @template T the answer's type
   * @param {string} key
   * @param {P.ToWorker} message
   * @returns {Promise<T>}
   */
  ask(key, message) {
    return new Promise((resolve, reject) => {
      this.pending.set(key, { resolve, reject });
      /** @type {Worker} */ (this.worker).postMessage(message);
    });
  }

  /**
   * Runs a stateless job of the worker (protocol.js's Jobs); resolves with its result. The
   * messages its reply may hold (the tools', the laws', the challenges') are loaded first.
   * @template {keyof P.Jobs} K
   * @param {K} kind
   * @param {P.Jobs[K]['req']} [data]
   * @returns {Promise<P.Jobs[K]['result']>}
   */
  async job(kind, data = /** @type {P.Jobs[K]['req']} */ ({})) {
    await loadRest();
    const job = ++this.req;
    return this.ask(`job ${job}`, /** @type {P.JobMessage} */ ({ type: 'job', job, kind, ...data }));
  }

  /**
   * The challenge measures of run `id`, if the worker still holds it (else null), said.
   * @param {number} id
   * @returns {Promise<Extract<P.ToPage, {type: 'challenge-measured'}>['measures']>}
   */
  measure(id) {
    return this.ask(`measure ${id}`, { type: 'challenge-measure', id });
  }

  /**
   * Settles the request `key`: rejects it with `error` (a text, or the core's message, said in
   * the language shown) when there is one, else resolves it with `result`.
   * @param {string} key
   * @param {string | null | undefined} error
   * @param {unknown} [result]
   */
  answer(key, error, result) {
    const p = this.pending.get(key);
    this.pending.delete(key);
    if (error != null) p?.reject(new Error(error));
    else p?.resolve(result);
  }

  /**
   * Settles the request a reply answers, or hands an unprompted message to the page's handler
   * of its type.
   * @param {P.ToPage} data
   */
  receive(data) {
    if (data.type === 'job') {
      this.answer(`job ${data.job}`, jobError(data), data.result);
    } else if (data.type === 'challenge-measured') {
      this.answer(`measure ${data.id}`, data.error, data.measures);
    } else if (data.type === 'described') {
      this.answer(`describe ${data.req}`, null, data.checked);
    } else if (data.type === 'invalid' && data.req !== undefined) {
      this.answer(`describe ${data.req}`, data.message);
    } else {
      if (data.type === 'ready') this.ready = true;
      const handler = /** @type {(data: P.ToPage) => void} */ (this.handlers[data.type]);
      handler(data);
    }
  }

  /**
   * The worker crashed (a trap in the core, or an uncaught error): it and everything it held (the
   * run, the pins) are gone. Ends what waited on it and starts a fresh one, unless it never
   * started, which a restart would only repeat.
   * @param {string} reason
   */
  fail(reason) {
    this.failures++;
    /** @type {Worker} */ (this.worker).terminate();
    for (const { reject } of this.pending.values()) reject(new WorkerFailed(reason));
    this.pending.clear();
    const restarting = this.ready;
    this.onFailed(reason, restarting);
    if (restarting) this.start();
  }
}
