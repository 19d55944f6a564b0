// Published runs never change: the CSV of every preset and of a few `v=1` links with overrides
// has the SHA-256 recorded in fixtures/published.json, written by `imlab run` of the build that
// published them. A change to the core that moves one bit of one of them fails here; a speed-up
// that must change bits goes behind a new scenario version instead.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';

const cli = new URL('../target/release/imlab', import.meta.url).pathname;
const published = JSON.parse(readFileSync(new URL('./fixtures/published.json', import.meta.url), 'utf8'));

test('every preset is among the published runs', () => {
  const presets = execFileSync(cli, ['list'])
    .toString()
    .trim()
    .split('\n')
    .map((l) => l.split(/\s+/)[0]);
  for (const p of presets) assert.ok(p in published, `preset ${p} has no recorded CSV`);
});

for (const [link, sha] of Object.entries(published)) {
  test(`the CSV of ${link} is as published`, () => {
    const csv = execFileSync(cli, ['run', link], { maxBuffer: 1 << 30 });
    assert.equal(createHash('sha256').update(csv).digest('hex'), sha);
  });
}
