// A message of the core (crate/src/text/message.rs) as it crosses from the worker: its id in
// web/locales/LANG/core-*.ftl and its arguments. The worker passes it on as it is; the page says it
// in the language shown (l10n.js).

/**
 * @typedef {{id: string, args: Record<string, CoreArg>}} CoreMessage
 * @typedef {string | number | {real: number} | {fixed: number, fraction: number} | {sci: number, places: number} | CoreMessage | CoreMessage[]} CoreArg
 */

/**
 * A value of the core as the page reads it: every message of the core in it said, as text in the
 * language shown (l10n.js, spoken); typed arrays as they are, arrays and tuples as arrays and
 * tuples.
 * @template T
 * @typedef {T extends CoreMessage
 *   ? string
 *   : T extends ArrayBufferView
 *     ? T
 *     : T extends object
 *       ? {[K in keyof T]: Spoken<T[K]>}
 *       : T} Spoken
 */

/**
 * Whether `value` is a message of the core.
 * @param {unknown} value
 * @returns {value is CoreMessage}
 */
export const isCoreMessage = (value) =>
  typeof value === 'object' &&
  value !== null &&
  typeof (/** @type {CoreMessage} */ (value).id) === 'string' &&
  'args' in value;

/**
 * What a thrown `error` says, for a message to the page: the core's message as it is, else its
 * text. The protocol types it as the text the page reads: the page's client says a core message in
 * the language shown (l10n.js, spoken) before any part of the page sees it.
 * @param {unknown} error
 * @returns {string}
 */
export const refusal = (error) => /** @type {string} */ (isCoreMessage(error) ? error : String(error));
