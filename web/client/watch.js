// What every client of a worker does with it: its messages to `onMessage`, and every way it can
// fail (its 'crashed' message, an uncaught error, a message that cannot be read) to `onFail`
// once, with the reason in words.
import { spoken, t } from '../l10n/l10n.js';

/** @import * as P from '../worker/protocol.js' */

/**
 * Why a worker crashed, in words, from its 'crashed' message.
 * @param {P.Crashed} crashed
 */
export function crashReason({ message, panic, memory }) {
  if (panic) return t('worker-crash-panic', { error: message, panic });
  return memory ? t('worker-crash-memory', { error: message }) : message;
}

/**
 * Why a worker failed, in words, from its error event's message (empty when the browser gives none).
 * @param {string} message
 */
export const errorReason = (message) => message || t('worker-unknown-error');

/** Why a worker failed when a message from it could not be read. */
export const unreadable = () => t('worker-unreadable');

/**
 * Why a job failed, in words, from its reply: the core's error, or the tools not loaded.
 * @param {Pick<P.JobReply, 'error' | 'unloaded'>} reply
 */
export const jobError = ({ error, unloaded }) =>
  unloaded ? t('worker-tools-not-loaded', { reason: error ?? '' }) : error;

/**
 * Wires `worker` to `onMessage(data)` and `onFail(reason)`.
 * @param {Worker} worker
 * @param {{onMessage: (data: P.ToPage) => void, onFail: (reason: string) => void}} handlers
 */
export function watch(worker, { onMessage, onFail }) {
  worker.onmessage = (/** @type {MessageEvent<P.FromWorker>} */ { data }) => {
    if (data.type === 'crashed') onFail(crashReason(data));
    else onMessage(spoken(data));
  };
  worker.onerror = (e) => {
    e.preventDefault();
    onFail(errorReason(e.message));
  };
  worker.onmessageerror = () => onFail(unreadable());
}
