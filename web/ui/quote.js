// How a message quotes input: one part escaped and cut, a list bounded.
import { t } from '../l10n/l10n.js';

// The characters a message escapes: the Unicode categories Cc, Cf, Zl and Zp, as the core's.
const INVISIBLE = /[\p{Cc}\p{Cf}\p{Zl}\p{Zp}]/u;
/** @type {Partial<Record<string, string>>} */
const ESCAPES = { '\n': '\\n', '\t': '\\t', '\r': '\\r' };

/**
 * `text` as a message quotes it (address parts can be any length and hold any character), as the
 * core's `excerpt` (crate/src/text/quote.rs) does: the characters that do not show or that
 * reorder the text around them escaped as Rust writes them (`\n`, `\u{202e}`), cut to 40
 * characters with the full length noted. The main thread holds no instance of the core (one there would compile the
 * module a second time before the worker starts, delaying the first run), so tests/quote.test.mjs
 * checks this against the core's, exported through the bindings, for every code point.
 * @param {string} text
 * @param {number} [max]
 */
export function excerpt(text, max = 40) {
  const chars = [...text];
  const shown = chars
    .slice(0, max)
    .map((c) =>
      INVISIBLE.test(c) ? (ESCAPES[c] ?? `\\u{${/** @type {number} */ (c.codePointAt(0)).toString(16)}}`) : c,
    )
    .join('');
  return chars.length > max ? `${shown}… (${chars.length} characters)` : shown;
}

/**
 * The first few `items` joined by `sep`, and how many more there are: a message quotes a bounded
 * number of parts of an address, however many it holds.
 * @param {string[]} items
 * @param {string} [sep]
 */
export function listed(items, sep = ', ') {
  const shown = items.slice(0, LISTED).join(sep);
  return items.length > LISTED ? t('list-more', { list: shown, count: items.length - LISTED }) : shown;
}
const LISTED = 5;
