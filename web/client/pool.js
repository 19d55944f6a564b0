// A pool of workers for stateless jobs (sweeps, seed runs, maps, challenge checks): one job a
// worker at a time, results in job order, Cancel that stops at once, a crashed worker replaced.
import { WORKER_URL } from '../worker-url.js';
import { jobError, watch } from './watch.js';
import { loadRest, t } from '../l10n/l10n.js';

/** @import * as P from '../worker/protocol.js' */

/**
 * A reply a member waits for: the worker's 'ready', or a job's reply.
 * @typedef {{type: 'ready' | 'job', job: number | undefined, resolve: (data: P.Spoken<P.Ready | P.JobReply>) => void,
 *   reject: (error: Error) => void}} Waiting
 */

/**
 * One worker of a pool. A crash (the worker's 'crashed' message, or an error event) terminates
 * it and rejects the reply it was waiting for; the pool then starts a fresh one.
 */
class Member {
  constructor() {
    // A pool's worker answers stateless jobs only: `role=pool` tells it to hold no pins and to
    // skip the run worker's warm-up.
    this.worker = new Worker(new URL('?role=pool', WORKER_URL), { type: 'module' });
    /** @type {string | null} why the worker failed */
    this.failed = null;
    /** @type {Waiting | null} the reply awaited */
    this.waiting = null;
    watch(this.worker, {
      onMessage: (data) => {
        if (
          this.waiting &&
          data.type === this.waiting.type &&
          /** @type {{job?: number}} */ (data).job === this.waiting.job
        ) {
          const { resolve } = this.waiting;
          this.waiting = null;
          resolve(data);
        }
      },
      onFail: (reason) => this.fail(reason),
    });
    this.ready = this.reply('ready');
  }

  /**
   * Resolves with the worker's next message of `type` (for `job`), or rejects if it fails first.
   * A newer wait (another run took the pool) cancels the older one.
   * @overload
   * @param {'ready'} type
   * @returns {Promise<P.Spoken<P.Ready>>}
   */
  /**
   * @overload
   * @param {'job'} type
   * @param {number} job
   * @returns {Promise<P.Spoken<P.JobReply>>}
   */
  /**
   * @param {Waiting['type']} type
   * @param {number} [job]
   * @returns {Promise<P.Spoken<P.Ready | P.JobReply>>}
   */
  reply(type, job) {
    this.waiting?.reject(new Error('cancelled'));
    return new Promise((resolve, reject) => {
      if (this.failed) reject(new Error(t('pool-worker-failed', { reason: this.failed })));
      else this.waiting = { type, job, resolve, reject };
    });
  }

  /**
   * Ends the worker for `reason`, rejecting the reply awaited with `error`.
   * @param {string} reason
   * @param {Error} [error]
   */
  fail(reason, error = new Error(t('pool-worker-failed-restart', { reason }))) {
    if (this.failed) return;
    this.failed = reason;
    this.worker.terminate();
    this.waiting?.reject(error);
    this.waiting = null;
  }
}

/** Workers running stateless jobs; results come back in job order. */
export class Pool {
  /** @param {number} size */
  constructor(size) {
    this.size = size;
    /** @type {Member[]} */
    this.members = [];
    this.generation = 0;
    this.jobs = 0; // job ids, unique over the pool's life so a late reply never matches a new job
  }

  /** Brings the pool to `size` live workers and waits until each has loaded the core. */
  async start() {
    for (const m of this.members.splice(this.size)) m.worker.terminate();
    this.members = this.members.filter((m) => !m.failed);
    while (this.members.length < this.size) this.members.push(new Member());
    await Promise.all(this.members.map((m) => m.ready));
  }

  /**
   * Runs `jobs` (messages without `type`/`job`); `onDone(count, index, result)` reports each
   * job as it ends, so that a caller can keep what finished before a cancel. The jobs of one
   * call are of one kind, so the results are of that kind's type.
   * @template {keyof P.Jobs} K
   * @param {({kind: K} & P.Jobs[K]['req'])[]} jobs
   * @param {(count: number, index: number, result: P.Jobs[K]['result']) => void} [onDone]
   * @returns {Promise<P.Jobs[K]['result'][]>}
   */
  async run(jobs, onDone = () => {}) {
    // The messages the replies may hold are loaded first (see RunClient.job); a Cancel meanwhile
    // cancels this run.
    const generation = ++this.generation;
    await Promise.all([this.start(), loadRest()]);
    if (this.generation !== generation) throw new Error('cancelled');
    /** @type {P.Jobs[K]['result'][]} */
    const results = new Array(jobs.length);
    let next = 0;
    let done = 0;
    let failed = false; // a job failed: the other workers stop after their current one
    const work = async (/** @type {Member} */ member) => {
      while (next < jobs.length) {
        if (this.generation !== generation || failed) throw new Error('cancelled');
        const index = next++;
        const job = ++this.jobs;
        const reply = member.reply('job', job);
        const message = /** @type {P.JobMessage} */ ({ type: 'job', job, ...jobs[index] });
        member.worker.postMessage(message);
        const data = await reply;
        if (data.error) throw new Error(jobError(data));
        const result = /** @type {P.Jobs[K]['result']} */ (data.result);
        results[index] = result;
        onDone(++done, index, result);
      }
    };
    try {
      await Promise.all(this.members.map(work));
    } catch (e) {
      failed = true;
      throw e;
    }
    return results;
  }

  /** Ends every worker of the pool (a later run starts fresh ones): a pool used now and then holds no core meanwhile. */
  close() {
    this.generation++;
    for (const m of this.members.splice(0)) m.fail('closed', new Error('cancelled'));
  }

  /**
   * Stops the jobs under way at once: a job runs in one call, so the workers that hold one are
   * terminated (the next run starts fresh ones) rather than waited for.
   */
  cancel() {
    this.generation++;
    for (const m of this.members) if (m.waiting) m.fail('cancelled', new Error('cancelled'));
  }
}
