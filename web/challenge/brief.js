// A challenge's task in words as the core gives it, paragraphs of its messages, said in the
// language shown and laid out as `imlab challenge` writes it.

/** @import * as P from '../worker/protocol.js' */

/**
 * The core's task in words: paragraphs, each a line and the lines of a list under it.
 * @typedef {P.Jobs['challenge']['result']['brief']} Brief
 */

/**
 * `brief` as text: each paragraph's first line, the lines of its list under it indented by two
 * spaces, a blank line between paragraphs and a line end after the last line.
 * @param {Brief} brief
 */
export const briefText = (brief) =>
  brief.paragraphs.map((p) => `${p.head}\n${p.items.map((item) => `  ${item}\n`).join('')}`).join('\n');
