// The run client: the simulation worker, which owns the core, and the page's messages with it.
// Describe requests, jobs and challenge measures are answered as promises; every other message
// goes to the page's handler of its type. A worker that fails is replaced.
import { WORKER_URL } from '../worker-url.js';
import { watch } from './watch.js';

/** A request the worker could not answer because it failed; the page has said so already. */
export class WorkerFailed extends Error {}

export class RunClient {
  /**
   * `onFailed(reason, restarting)` tells the page that the worker failed; `restarting` is false
   * when it never started, which a restart would only repeat.
   */
  constructor(onFailed) {
    this.onFailed = onFailed;
    this.handlers = {}; // the page's handlers of the worker's messages, by type
    this.worker = null;
    this.ready = false; // whether the current worker has loaded the core
    this.req = 0;
    this.pending = new Map(); // requests awaiting their answer: key → {resolve, reject}
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
          if (data.type === 'crashed') this.fail(data.message);
          else this.receive(data);
        } catch (e) {
          reportError(e);
        }
      }
      if (boot.failure && this.failures === failures) this.fail(boot.failure);
    });
  }

  listen() {
    watch(this.worker, { onMessage: (data) => this.receive(data), onFail: (reason) => this.fail(reason) });
  }

  post(message) {
    this.worker.postMessage(message);
  }

  /** Asks the core to validate and describe a scenario string ('recover' keeps its good fields). */
  describe(scenario, type = 'describe') {
    const req = ++this.req;
    return this.ask(`describe ${req}`, { type, req, scenario });
  }

  /** Sends `message` and resolves with the answer that carries `key` (see receive). */
  ask(key, message) {
    return new Promise((resolve, reject) => {
      this.pending.set(key, { resolve, reject });
      this.worker.postMessage(message);
    });
  }

  /** Runs a stateless job of the worker (its JOBS table); resolves with its result. */
  job(kind, data = {}) {
    const job = ++this.req;
    return this.ask(`job ${job}`, { type: 'job', job, kind, ...data });
  }

  /** The challenge measures of run `id`, if the worker still holds it (else null). */
  measure(id) {
    return this.ask(`measure ${id}`, { type: 'challenge-measure', id });
  }

  /** Settles the request `key`: rejects it with `error` when there is one, else resolves it with `result`. */
  answer(key, error, result) {
    const p = this.pending.get(key);
    this.pending.delete(key);
    if (error != null) p?.reject(new Error(error));
    else p?.resolve(result);
  }

  receive(data) {
    const { type, req } = data;
    if (type === 'job') {
      this.answer(`job ${data.job}`, data.error, data.result);
    } else if (type === 'challenge-measured') {
      this.answer(`measure ${data.id}`, data.error, data.measures);
    } else if (type === 'described') {
      this.answer(`describe ${req}`, null, data.info);
    } else if (type === 'invalid' && req !== undefined) {
      this.answer(`describe ${req}`, data.message);
    } else {
      if (type === 'ready') this.ready = true;
      this.handlers[type](data);
    }
  }

  /**
   * The worker crashed (a trap in the core, or an uncaught error): it and everything it held (the
   * run, the pins) are gone. Ends what waited on it and starts a fresh one, unless it never
   * started, which a restart would only repeat.
   */
  fail(reason) {
    this.failures++;
    this.worker.terminate();
    for (const { reject } of this.pending.values()) reject(new WorkerFailed(reason));
    this.pending.clear();
    const restarting = this.ready;
    this.onFailed(reason, restarting);
    if (restarting) this.start();
  }
}
