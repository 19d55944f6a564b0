// The worker's challenge jobs (web/worker/challenge-jobs.js) in Node, on the core the page ships: each
// built-in's known solution passes on every run and its untouched base fails; a submission
// outside the challenge is refused naming the field; a bad challenge throws the core's message; a
// composer's check gets its designs from the core.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { initSync } from '../dist/pkg/imlab.js';
import { CHALLENGE_JOBS as jobs } from '../dist/.src/worker/challenge-jobs.js';
import { english } from './core-english.mjs';

initSync({ module: readFileSync(new URL('../dist/pkg/imlab_bg.wasm', import.meta.url)) });

/** The verdict on `submission` of challenge `text`, every run measured by the 'challenge-run' job. */
function grade(text, submission) {
  const sub = jobs['challenge-submission']({ text, submission });
  assert.equal(sub.kind, 'ok', sub.message && english(sub.message));
  const runs = sub.scenarios.map((scenario) => jobs['challenge-run']({ scenario }));
  return jobs['challenge-judge']({ text, runs });
}

test('each built-in passes with its solution and fails untouched', () => {
  const builtins = jobs['challenge-builtins']({});
  assert.deepEqual(
    builtins.map((b) => b.name),
    ['step-tune', 'load-observer', 'ifoc-load'],
  );
  for (const b of builtins) {
    const desc = jobs.challenge({ text: b.name });
    assert.equal(desc.encoded, b.text);
    const solved = `${b.text}${b.solution
      .split('&')
      .map((p) => `&try.${p}`)
      .join('')}`;
    assert.equal(grade(b.text, solved).pass, true, `${b.name} solved`);
    assert.equal(grade(b.text, b.text).pass, false, `${b.name} untouched`);
  }
});

test('a refused submission names the field; a bad challenge throws the message', () => {
  const text = jobs.challenge({ text: 'step-tune' }).encoded;
  const sub = jobs['challenge-submission']({ text, submission: `${text}&try.ekf=rk4` });
  assert.equal(sub.kind, 'refused');
  assert.equal(english(sub.message), "field 'ekf' is not allowed");
  assert.equal(english(sub.status), "refused: field 'ekf' is not allowed");
  assert.deepEqual(sub.scenarios, []);
  // The core's message, its id and arguments, for the page to say in its language.
  assert.throws(
    () => jobs.challenge({ text: 'c=1&title=x&base=v%3D1%26preset%3Dstep&need.nothing=max:1' }),
    (e) => e.id === 'challenge-need-unknown-figure' && /'nothing' is not a figure/.test(english(e)),
  );
});

test('a run that runs away fails every criterion, with the reason, however lenient the bound', () => {
  const base = encodeURIComponent('v=1&preset=step&model.rr=20&duration=0.2');
  const text = jobs.challenge({
    text: `c=1&title=x&base=${base}&allow.k1=300..5000&need.current_peak=max:1000`,
  }).encoded;
  const verdict = grade(text, text);
  assert.equal(verdict.pass, false);
  assert.equal(verdict.criteria[0].pass, false);
  assert.match(english(verdict.criteria[0].reason), /ran away/);
  assert.equal(english(verdict.criteria[0].label), 'peak stator current |i_s|');
  assert.equal(english(verdict.criteria[0].bound), '≤ 1000 A');
  const figures = jobs['challenge-figures']({});
  assert.ok(figures.some((f) => f.name === 'load_recovery_time'));
  // The bounds each figure may take, the first offered and the one a composer starts with.
  const policy = (name) => figures.find((f) => f.name === name);
  assert.deepEqual([policy('mean_nis').ops, policy('mean_nis').op], [['band', 'max', 'min'], 'band']);
  assert.deepEqual([policy('speed_error_final').ops, policy('speed_error_final').op], [['max', 'min', 'abs'], 'abs']);
  assert.equal(policy('current_peak').op, 'max');
});

test('a check’s designs: [field, value] pairs within the allowed ranges, the base first, as many as asked', () => {
  const text = jobs.challenge({ text: 'step-tune' }).encoded;
  const designs = jobs['challenge-designs']({ text, max: 40 });
  assert.equal(designs.length, 40);
  assert.deepEqual(designs[0], []);
  assert.deepEqual(designs.slice(1, 3), [[['k1', '300']], [['k1', '5000']]]);
  for (const tries of designs) assert.equal(jobs['challenge-tries']({ text, tries }).kind, 'ok');
  assert.deepEqual(jobs['challenge-designs']({ text, max: 40 }), designs);
});
