// The worker's runtime: how it posts to the page, yields to the page's messages between slices
// of work, and reports a crash of the core once.
import { panic_message } from '../../pkg-run/imlab.js';
import { refusal } from '../l10n/core-message.js';

/** @typedef {import('./protocol.js').FromWorker} FromWorker */
/** @typedef {import('./protocol.js').View} View */

// A slice of work between two looks at the message queue (ms of the worker's clock, read by the
// core): Cancel is honoured within it, and optimised code compiled in the background is picked
// up at the next slice. Bounded by time, as one sample can cost a thousand ordinary ones.
export const SLICE_MS = 4;

let crashed = false;

/** Where a panic's text is read after a trap: the run's core, and the tools' once loaded. */
const panicSources = [panic_message];

/** Adds a module whose last panic a crash report reads (the tools' core, when it is loaded). */
export const addPanicSource = (/** @type {() => string | undefined} */ source) => void panicSources.push(source);

/** Whether the core has trapped: from then on nothing calls it. */
export const isCrashed = () => crashed;

/**
 * Posts `message` to the page, transferring the buffers of `view` (or `transfer`) rather than
 * copying them.
 * @param {FromWorker} message
 * @param {View | null} [view]
 * @param {Transferable[]} [transfer]
 */
export function post(message, view = null, transfer = []) {
  const buffers = view
    ? Object.values(view.plots).flatMap((p) => [p.t.buffer, ...Object.values(p.columns).map((a) => a.buffer)])
    : transfer;
  self.postMessage(message, buffers);
}

/**
 * Reports a crash to the page once: `error` is a trap or an error nothing caught. A trap can
 * leave the instance half-way through a call (a borrow held, memory exhausted), so from here on
 * nothing calls the core: messages are ignored and no awaited yield resumes.
 * @param {unknown} error
 */
export function crash(error) {
  if (crashed) return;
  crashed = true;
  let panic;
  for (const source of panicSources) {
    try {
      panic ??= source();
    } catch {
      // The instance is too broken to read the message; the trap's own text still tells.
    }
  }
  const message = error instanceof Error ? `${error.name}: ${error.message}` : String(error);
  // A Rust allocation failure aborts without a panic, as an 'unreachable' trap.
  const memory = !panic && error instanceof WebAssembly.RuntimeError && /unreachable/.test(error.message);
  post({ type: 'crashed', message, panic, memory });
}

/**
 * Reports `e` as a crash when it is a trap (not a clean error thrown by the core); returns whether it was.
 * @param {unknown} e
 */
export function trapped(e) {
  if (!(e instanceof WebAssembly.RuntimeError)) return false;
  crash(e);
  return true;
}

/**
 * Tells the page that the core refused run `id`'s request with `e`, or reports a crash when `e`
 * is a trap.
 * @param {unknown} e
 * @param {number} id
 */
export function refuse(e, id) {
  if (!trapped(e)) post({ type: 'invalid', id, message: refusal(e) });
}

self.addEventListener('unhandledrejection', (e) => {
  e.preventDefault();
  crash(e.reason);
});
self.addEventListener('error', (e) => {
  e.preventDefault();
  crash(e.error ?? e.message);
});

// Lets queued messages (a cancel) run between chunks. A MessageChannel round trip is not
// clamped to 4 ms the way nested setTimeout(0) is. After a crash no yield resumes, so no loop
// goes on calling the core.
const channel = new MessageChannel();
/** @type {(() => void)[]} */
const waiting = [];
channel.port1.onmessage = () => {
  const resume = waiting.shift();
  if (!crashed) resume?.();
};

/** @returns {Promise<void>} */
export function yieldToMessages() {
  return new Promise((resolve) => {
    waiting.push(resolve);
    channel.port2.postMessage(null);
  });
}
