// What every client of a worker does with it: its messages to `onMessage`, and every way it can
// fail (its 'crashed' message, an uncaught error, a message that cannot be read) to `onFail`
// once, with the reason in words.

/** @import * as P from '../worker/protocol.js' */

/**
 * Wires `worker` to `onMessage(data)` and `onFail(reason)`.
 * @param {Worker} worker
 * @param {{onMessage: (data: P.FromWorker) => void, onFail: (reason: string) => void}} handlers
 */
export function watch(worker, { onMessage, onFail }) {
  worker.onmessage = (/** @type {MessageEvent<P.FromWorker>} */ { data }) => {
    if (data.type === 'crashed') onFail(data.message);
    else onMessage(data);
  };
  worker.onerror = (e) => {
    e.preventDefault();
    onFail(e.message || 'unknown error');
  };
  worker.onmessageerror = () => onFail('a message from it could not be read');
}
