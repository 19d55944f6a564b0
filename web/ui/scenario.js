// Reading the core's description of a scenario (its `describe`): the page reads fields from it,
// never from the scenario's text.

/** @import * as P from '../worker/protocol.js' */

/**
 * The value the scenario holds for `key`, as the codec writes it, or null (also while no
 * scenario is loaded: `state.info` is null until one is).
 * @param {P.Info | null} info
 * @param {string} key
 */
export function fieldValue(info, key) {
  return info?.fields.find((f) => f.key === key)?.value ?? null;
}
