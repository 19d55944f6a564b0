// The page quotes address parts on its main thread, which holds no instance of the core: its
// `excerpt` (web/ui/url.js) must write what the core's (crate/src/text/quote.rs, the CLI's)
// writes.
// Checked in Node against the core's binding for every code point, in strings of a few at a time
// (escaping is per character), and for the cut of long input.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { initSync, excerpt as core } from '../dist/pkg/imlab.js';
import { excerpt as page } from '../web/ui/quote.js';

initSync({ module: readFileSync(new URL('../dist/pkg/imlab_bg.wasm', import.meta.url)) });

// Below the 40-character cut, so each string is compared whole.
const PER_STRING = 32;

test('the page escapes every code point as the core does', () => {
  let escaped = 0;
  for (let first = 0; first <= 0x10ffff; first += PER_STRING) {
    const chars = [];
    for (let u = first; u < first + PER_STRING && u <= 0x10ffff; u++) {
      // Lone surrogates are not characters: the bindings pass text as UTF-8.
      if (u < 0xd800 || u > 0xdfff) chars.push(String.fromCodePoint(u));
    }
    const text = chars.join('');
    const expected = core(text);
    assert.equal(page(text), expected, `from U+${first.toString(16)}`);
    escaped += (expected.match(/\\u\{|\\[ntr]/g) ?? []).length;
  }
  // The 25 ranges of Cc, Cf, Zl and Zp hold 237 code points (Unicode 16).
  assert.equal(escaped, 237);
});

test('long input is cut as the core cuts it, the escapes after the cut', () => {
  for (const text of ['\u202e'.repeat(100), `${'a'.repeat(39)}\u2066bc`, `😀${'\u200d'.repeat(45)}`, 'short\n']) {
    assert.equal(page(text), core(text));
  }
  assert.equal(page('k\u202e1'), 'k\\u{202e}1');
});
