// Reading the core's description of a scenario (its `describe`): the page reads fields from it,
// never from the scenario's text.

/** @import * as P from '../worker/protocol.js' */

/**
 * The value the scenario holds for `key`, as the codec writes it, or null. `info` may be the
 * page's description (`state.info`, null until a scenario is loaded), which is read only once one
 * is loaded.
 * @param {P.Info | null} info
 * @param {string} key
 */
export function fieldValue(info, key) {
  return /** @type {P.Info} */ (info).fields.find((f) => f.key === key)?.value ?? null;
}
