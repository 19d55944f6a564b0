// "Write this step": a student's own law on the page. It is typeset as it is typed and a bad one
// is marked at its place; run, it gets the core's verdict against the step's designed dynamics and
// its residual is plotted; a bad formula loses nothing else of the scenario.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { browserSuite, openWalkthrough, startRun } from './browser.mjs';

const suite = browserSuite();
const BASE = '?v=1&preset=step&duration=0.05&k1=900';
const PAPER_V1 = '-si1 + dwd + a3*wd + a2 - k1s1*z1';

/** The step-1 law's field in the walkthrough. */
const field = (page) => page.locator('#section-step1 .law input.formula');

/** Writes `text` as step 1's law and runs it (Enter); resolves with how the run ended. */
async function runLaw(page, text) {
  await field(page).fill(text);
  return startRun(page, () => field(page).press('Enter'));
}

/** The step-1 residual plot's samples (the chart whose series is law_r1), once drawn for the run. */
const residuals = (page) =>
  page.evaluate(() => {
    const set = window.imlab.walkthrough;
    const i = set.defs.findIndex((d) => d.series.some((s) => s[0] === 'law_r1'));
    return Array.from(set.charts[i].data[1]);
  });

test('a law of step 1 is typeset as it is typed, run at 20 kHz, judged, and its residual plotted', () =>
  suite.withPage(BASE, async (page) => {
    await openWalkthrough(page);
    // k1 where the paper has k1s1 = k1 − a3: off by a3·z1, a few parts in a hundred thousand.
    assert.equal(await runLaw(page, '-si1 + dwd + a3*wd + a2 - k1*z1'), 'done');
    assert.match(new URL(page.url()).search, /law\.v1=/);
    await page.waitForSelector('#section-step1 .law-preview .katex');
    const verdict = await page.textContent('#section-step1 .law-verdict');
    assert.match(verdict, /does not give the designed dynamics ż1 = −k1·z1 \+ z2/);
    assert.match(verdict, /k1 where \(28\) has k1s1/);
    // The other steps keep the paper's law, and say so.
    assert.match(await page.textContent('#section-step2 .law-verdict'), /paper’s v2/);
    // The residual is a3·z1 at each sample: finite, and not zero once z1 is.
    await page.waitForFunction(() => window.imlab.walkthrough.charts.length === window.imlab.walkthrough.defs.length);
    const wrong = await residuals(page);
    assert.ok(wrong.length > 100 && wrong.every(Number.isFinite));
    assert.ok(
      wrong.some((r) => Math.abs(r) > 1e-9),
      'a residual away from zero',
    );

    // The paper's own law, written in the language: the designed dynamics, and a zero residual.
    assert.equal(await runLaw(page, PAPER_V1), 'done');
    assert.match(await page.textContent('#section-step1 .law-verdict'), /gives the designed dynamics/);
    await page.waitForFunction(() => window.imlab.walkthrough.charts.length === window.imlab.walkthrough.defs.length);
    assert.ok((await residuals(page)).every((r) => r === 0));

    // The settings' own-law field shows the same verdict.
    await page.click('details[data-group=law] > summary');
    await page.waitForFunction(() => {
      const [own, settings] = ['#section-step1 .law-verdict', '#settings .law-field .law-verdict'].map(
        (s) => document.querySelector(s)?.textContent,
      );
      return own === settings && /gives the designed dynamics/.test(own ?? '');
    });
    // A formula edited since the run, here one that does not parse, is not what the verdict is
    // about: the verdict says which law it is of, and is neither good nor bad.
    await field(page).fill('-si1 + dwd + foo*wd');
    await page.waitForSelector('#section-step1 .law-verdict.stale');
    const stale = await page.textContent('#section-step1 .law-verdict');
    assert.ok(stale.startsWith('Not the law typed:') && stale.includes(`v1 = ${PAPER_V1}`), stale);
    assert.equal(await page.locator('#section-step1 .law-verdict.good').count(), 0);
    // The law that ran, typed back: the verdict is of it again.
    await field(page).fill(PAPER_V1);
    await page.waitForSelector('#section-step1 .law-verdict.good');
    assert.equal(await page.locator('#section-step1 .law-verdict.stale').count(), 0);
  }));

test('a formula that does not parse is marked at its place, and the rest of the scenario stays', () =>
  suite.withPage(BASE, async (page) => {
    await openWalkthrough(page);
    const before = await page.evaluate(() => document.body.dataset.scenario);
    await field(page).fill('-si1 + dwd + foo*wd');
    await page.waitForSelector('#section-step1 .law-error');
    assert.equal(
      await page.textContent('#section-step1 .law-error'),
      "At character 14: unknown name 'foo' (see the list of names)",
    );
    assert.equal(await page.textContent('#section-step1 .law-preview mark'), 'foo');
    // Checked by the core as a field: marked there too, and not run; k1 and the length stay.
    await field(page).press('Enter');
    await page.waitForSelector('#section-step1 .law .knob-error');
    assert.equal(await page.evaluate(() => document.body.dataset.scenario), before);
    assert.equal(await page.inputValue('#field-k1'), '900');
    // A formula cut short is marked at its end.
    await field(page).fill('z1 *');
    await page.waitForFunction(() =>
      /At character 5/.test(document.querySelector('#section-step1 .law-error')?.textContent),
    );
  }));

test('a law link opens with the law in its field, typeset, and the names it may use listed', () =>
  suite.withPage(`${BASE}&law.v1=${encodeURIComponent(PAPER_V1)}`, async (page) => {
    await openWalkthrough(page);
    assert.equal(await field(page).inputValue(), PAPER_V1);
    await page.waitForSelector('#section-step1 .law-preview .katex');
    const names = await page.$$eval('#section-step1 .law-names td code', (cells) => cells.map((c) => c.textContent));
    assert.ok(names.includes('k1s1') && names.includes('si1'));
    // Step 1 may not read what step 1 defines; step 2 may.
    assert.ok(!names.includes('v1'));
    const step2 = await page.$$eval('#section-step2 .law-names td code', (cells) => cells.map((c) => c.textContent));
    assert.ok(step2.includes('v1') && step2.includes('z2'));
    // Each name's and function's meaning is the core's, said in the language shown.
    const x1h = await page.$$eval('#section-step1 .law-names tr', (trs) =>
      trs.map((tr) => [...tr.querySelectorAll('td')].map((td) => td.textContent)).find((cells) => cells[0] === 'x1h'),
    );
    assert.deepEqual([x1h?.[2], x1h?.[3]], ['rad/s', 'estimated rotor speed ω̂ (posterior x̂1)']);
    const functions = await page.textContent('#section-step1 .law-names p');
    assert.match(functions, /sqrt\(x\): square root; exp\(x\): exponential; /);
  }));

test('a law not finite at some drawn states is judged so with its cause, and its residual is no figure', () =>
  suite.withPage(BASE, async (page) => {
    await openWalkthrough(page);
    // The paper's v1 plus a term that overflows where z1 is large: fine on the run, not everywhere.
    assert.equal(await runLaw(page, `${PAPER_V1} + exp(10*abs(z1)) - 1`), 'done');
    await page.waitForFunction(() =>
      /not a finite number/.test(document.querySelector('#section-step1 .law-verdict')?.textContent ?? ''),
    );
    const verdict = await page.textContent('#section-step1 .law-verdict');
    assert.match(
      verdict,
      /your v1 \(rad\/s²\) is not a finite number at \d+ of the 200 drawn states: it gives inf at /,
    );
    assert.match(await page.textContent('#consistency'), /^law_residual is not a finite number: your v1/);
    assert.doesNotMatch(await page.textContent('body'), /Infinity|up to inf/);
  }));
