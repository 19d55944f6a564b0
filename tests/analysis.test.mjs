// Browser tests of the analysis tools: overlays, sweeps (parallel = serial = CLI), seeds, sharing.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { browserSuite, runAgain, settled, startRun } from './browser.mjs';

const cli = new URL('../target/release/imlab', import.meta.url).pathname;
const suite = browserSuite();
/** Opens the app at `path`, waits for its run, then runs `body(page)`. */
const withPage = (path, body) =>
  suite.withPage(path, async (page) => {
    assert.equal(await settled(page), 'done');
    await body(page);
  });

async function download(page, selector) {
  const [d] = await Promise.all([page.waitForEvent('download'), page.click(selector)]);
  return readFileSync(await d.path(), 'utf8');
}

const sweepDone = (page) =>
  page
    .waitForFunction(() => ['done', 'failed', 'cancelled'].includes(document.body.dataset.sweep), null, {
      timeout: 60_000,
    })
    .then(() => page.evaluate(() => document.body.dataset.sweep));

test('a pinned run is overlaid with a legend of what differs, and the comparison is shared by URL', async () => {
  let shared;
  await withPage('?v=1&preset=step', async (page) => {
    await page.click('#pin');
    await page.waitForSelector('#pins li');
    await page.fill('#field-k1', '600');
    await page.press('#field-k1', 'Tab');
    await page.waitForFunction(() => document.body.dataset.unrun === '1');
    await runAgain(page);
    assert.ok(page.url().includes('k1=600'));
    await page.waitForFunction(() => document.querySelectorAll('#overlay-plots .plot canvas').length === 2);
    // The legend follows the run the worker holds: it says what differs once the new run is held.
    await page.waitForFunction(() => document.getElementById('pins').textContent.includes('k1: 1200 → 600 1/s'));
    // The runs kept ω for the overlay; another column is read by one replay of each, then kept.
    // The envelope keeps every bucket's extremes, so its extremes are the CLI run's.
    const extremes = (values) => [Math.min(...values), Math.max(...values)];
    const column = (scenario, name) => {
      const csv = execFileSync(cli, ['run', scenario], { stdio: ['ignore', 'pipe', 'ignore'], maxBuffer: 1 << 30 });
      const [header, ...rows] = csv.toString().trim().split('\n');
      const c = header.split(',').indexOf(name);
      return rows.map((r) => Number(r.split(',')[c]));
    };
    for (const name of ['u_a', 'omega']) {
      await page.selectOption('#overlay-column', name);
      await page.waitForFunction((name) => window.imlab.overlay?.column === name, name);
      const [, current, pinned] = await page.evaluate(() => window.imlab.overlay.data.map((a) => [...a]));
      assert.deepEqual(extremes(current), extremes(column('v=1&preset=step&k1=600', name)), name);
      assert.deepEqual(extremes(pinned), extremes(column('v=1&preset=step', name)), name);
    }
    assert.match(await page.textContent('#overlay-plots .u-title'), /^speed ω: current run and pinned runs$/);
    shared = page.url();
    assert.match(shared, /#pins=v%3D1%26preset%3Dstep$/);
  });
  await withPage(shared.slice(suite.server.url.length), async (page) => {
    await page.waitForFunction(() => document.querySelectorAll('#overlay-plots .plot canvas').length === 2);
    assert.match(await page.textContent('#pins'), /pin 1: k1: 1200 → 600 1\/s/);
    await page.click('#pins button');
    await page.waitForFunction(
      () => document.querySelectorAll('#pins li').length === 0 && !location.hash.includes('pins'),
    );
  });
});

/** `imlab sweep SCENARIO ARGS...` as CSV text. */
const cliSweep = (scenario, ...args) =>
  execFileSync(cli, ['sweep', scenario, ...args], { stdio: ['ignore', 'pipe', 'ignore'] }).toString();

/** The column `name` of a sweep CSV's points, as numbers. */
function sweepColumn(csv, name) {
  const [header, ...lines] = csv
    .trim()
    .split('\n')
    .filter((l) => !l.startsWith('#'));
  const c = header.split(',').indexOf(name);
  return lines.map((l) => Number(l.split(',')[c]));
}

test('input quoted in a message has its invisible and reordering characters escaped, by the page as by the core', () =>
  // A pin whose key holds a right-to-left override: the page quotes the pin, the core the key.
  withPage(`?v=1&preset=step#pins=${encodeURIComponent('v=1&preset=step&k\u202e1=5')}`, async (page) => {
    await page.waitForFunction(() => document.getElementById('message').textContent.includes('not pin'));
    const message = await page.textContent('#message');
    assert.match(
      message,
      /ould not pin v=1&preset=step&k\\u\{202e\}1=5: field 'k\\u\{202e\}1' is not a scenario field/,
    );
    assert.doesNotMatch(message, /[\p{Cc}\p{Cf}\p{Zl}\p{Zp}]/u);
  }));

test("the core's words about pins are said in the page's language: a full set, and a pin the same as the run", () => {
  // Five pins, one more than the core keeps: the first is the run itself, the fifth is refused.
  const pin = (k1) => encodeURIComponent(`v=1&preset=step&duration=0.02${k1 ? `&k1=${k1}` : ''}`);
  const pins = ['', 600, 700, 800, 900].map(pin).join('|');
  return withPage(`?v=1&preset=step&duration=0.02#lang=de&pins=${pins}`, async (page) => {
    await page.waitForFunction(() => document.querySelectorAll('#pins li').length === 4);
    await page.waitForFunction(() => document.getElementById('message').textContent.includes('angeheftet'));
    assert.match(await page.textContent('#message'), /können höchstens 4 Läufe angeheftet werden/);
    const first = await page.textContent('#pins li');
    assert.match(first, /gleiches Szenario/);
  });
});

test('the browser sweep equals the CLI sweep, and parallel equals serial', () =>
  withPage('?v=1&preset=step#sweep=10,1000,12,0.02,0,0.2,euler.ifocpi', async (page) => {
    assert.equal(await sweepDone(page), 'done');
    const parallel = await download(page, '#sweep-csv');
    const expected = cliSweep('v=1&preset=step', '--freqs', '10:1000:12', '--amp', '0.02', '--duration', '0.2');
    assert.equal(parallel, expected);
    // The link's plan, given to the CLI as it is, runs the same variants: the first is the CSV above.
    const plan = cliSweep('v=1&preset=step', '--plan', '10,1000,12,0.02,0,0.2,euler.ifocpi');
    const [euler, ifocpiPlan] = plan.split(/^# variant=\w+\n/m).slice(1);
    assert.equal(euler, expected);
    assert.equal(await page.locator('#sweep-table tr[data-variant]').count(), 2);
    // The peak current each point needs, its largest in the table against the rated 4 A of the
    // step preset, for each variant as the CLI measures it.
    assert.match(parallel.split('\n')[0], /,peak_current_a$/);
    assert.equal(await page.textContent('#sweep-table th:nth-child(7)'), 'peak |i_s| (A)');
    const ifocpi = cliSweep(
      'v=1&preset=step&controller=ifoc',
      '--freqs',
      '10:1000:12',
      '--amp',
      '0.02',
      '--duration',
      '0.2',
    );
    assert.equal(ifocpiPlan, ifocpi);
    for (const [variant, csv] of [
      ['euler', expected],
      ['ifocpi', ifocpi],
    ]) {
      const peak = Math.max(...sweepColumn(csv, 'peak_current_a'));
      assert.ok(peak > 0 && peak < 4, `${variant}: ${peak}`);
      assert.equal(
        await page.textContent(`#sweep-table tr[data-variant=${variant}] td:nth-child(7)`),
        `${peak.toPrecision(3)} (rated 4.00)`,
      );
    }
    // The IFOC's PI alone at standstill never settles in 0.2 s runs (its MRAS is blind near zero
    // speed), so the core gives no bandwidth for it.
    assert.match(
      await page.textContent('#sweep-table tr[data-variant=ifocpi] td:nth-child(2)'),
      /^not given: it would rest on a point that had not settled$/,
    );
    await page.fill('#sweep-form [name=workers]', '1');
    await page.click('#sweep-run');
    await page.waitForFunction(() => document.getElementById('sweep-status').textContent.includes('on 1 worker.'));
    assert.equal(await download(page, '#sweep-csv'), parallel);
  }));

test('the points whose peak current is above the rated current are listed and marked', () =>
  withPage('?v=1&preset=step&i_rated=1.52#sweep=10,1000,4,0.02,0,0.2,euler', async (page) => {
    assert.equal(await sweepDone(page), 'done');
    const csv = cliSweep('v=1&preset=step&i_rated=1.52', '--freqs', '10:1000:4');
    assert.equal(await download(page, '#sweep-csv'), csv);
    const freqs = sweepColumn(csv, 'freq_hz');
    const peaks = sweepColumn(csv, 'peak_current_a');
    const above = freqs.filter((_, i) => peaks[i] > 1.52).map((f) => `${f.toPrecision(4)} Hz`);
    assert.deepEqual(above, ['215.4 Hz', '1000 Hz']);
    const cell = page.locator('#sweep-table tr[data-variant=euler] td:nth-child(7)');
    assert.equal(
      await cell.textContent(),
      `${Math.max(...peaks).toPrecision(3)} (rated 1.52); above the rating at 2: ${above.join(', ')}`,
    );
    assert.equal(await cell.getAttribute('class'), 'over-rating');
  }));

test("a sweep amplitude too small to measure is refused with the core's message, as by the CLI", () =>
  withPage('?v=1&preset=step#sweep=100,100,1,1e-200,0,0.05,euler', async (page) => {
    assert.equal(await sweepDone(page), 'failed');
    const status = await page.textContent('#sweep-status');
    assert.match(status, /field 'sine\.amp' = 1e-200: out of range, allowed an amplitude the sweep can measure/);
    assert.doesNotMatch(status, /inf|NaN/);
  }));

test('points that had not settled are drawn hollow, listed with the reason, and give no bandwidth', () =>
  // 0.2 s runs end while the IFOC still rings from its start (crate/tests/sweep.rs).
  withPage('?v=1&preset=ifoc-step#sweep=300,480,2,0.02,40,0.2,ifoc', async (page) => {
    assert.equal(await sweepDone(page), 'done');
    const cells = await page.locator('#sweep-table tr[data-variant=ifoc] td').allTextContents();
    assert.equal(cells[1], 'not given: it would rest on a point that had not settled');
    assert.equal(cells[5], '2: 300.0 Hz, 480.0 Hz');
    const reasons = await page.locator('#bode .sweep-unsettled li').allTextContents();
    assert.equal(reasons.length, 2);
    for (const r of reasons)
      assert.match(
        r,
        /^Classical IFOC \+ MRAS, torque feedforward, \d+\.0 Hz: not settled: over the last \d+ periods, .* changed by −?\d+\.\d\d dB and its phase by −?\d+\.\d°/,
      );
    // Each Bode plot has a series of hollow markers for them.
    assert.equal(
      await page
        .locator('#bode .u-legend', { hasText: 'Classical IFOC + MRAS, torque feedforward, not settled' })
        .count(),
      2,
    );
    assert.match(
      await download(page, '#sweep-csv'),
      /\n# bandwidth_hz=unsettled phase_at_200hz_deg=none unsettled=2\n$/,
    );
  }));

test('Cancel stops a sweep midway', () =>
  withPage('?v=1&preset=step', async (page) => {
    await page.click('[data-tab=analysis]');
    await page.fill('#sweep-form [name=n]', '60');
    await page.fill('#sweep-form [name=duration]', '1');
    await page.click('#sweep-run');
    await page.waitForFunction(() => document.getElementById('sweep-progress').value > 0);
    await page.click('#sweep-cancel');
    assert.equal(await sweepDone(page), 'cancelled');
    assert.ok(await page.evaluate(() => document.getElementById('sweep-progress').value < 1));
    assert.match(await page.textContent('#sweep-status'), /cancelled/);
  }));

test("a malformed sweep request is refused with the core's message, before any run", () =>
  withPage('?v=1&preset=step', async (page) => {
    await page.click('[data-tab=analysis]');
    await page.fill('#sweep-form [name=lo]', '-5');
    await page.click('#sweep-run');
    await page.waitForFunction(
      () => !['', 'Checking the sweep…'].includes(document.getElementById('sweep-status').textContent),
    );
    assert.match(await page.textContent('#sweep-status'), /^frequency grid -5:1000:20: expected 0 < lo ≤ hi/);
    assert.equal(await page.evaluate(() => document.body.dataset.sweep), undefined);
  }));

test('a seed sweep shows mean and min–max bands and its CSV equals the CLI', () =>
  withPage('?v=1&preset=step', async (page) => {
    await page.click('[data-tab=analysis]');
    await page.fill('#seeds-form [name=n]', '4');
    await page.click('#seeds-run');
    await page.waitForFunction(() => document.body.dataset.seeds === 'done', null, { timeout: 60_000 });
    assert.equal(await page.locator('#seeds-plots .plot canvas').count(), 2);
    const csv = await download(page, '#seeds-csv');
    const expected = execFileSync(cli, ['seeds', 'v=1&preset=step', '--n', '4'], {
      stdio: ['ignore', 'pipe', 'ignore'],
    }).toString();
    assert.equal(csv, expected);
  }));

test('a seed range past the largest seed is refused before any run, naming the range', () =>
  withPage('?v=1&preset=step&seed=9007199254740990', async (page) => {
    await page.click('[data-tab=analysis]');
    await page.fill('#seeds-form [name=n]', '4');
    await page.click('#seeds-run');
    await page.waitForFunction(() =>
      document.getElementById('seeds-status').textContent.startsWith('Seed sweep failed'),
    );
    assert.equal(
      await page.textContent('#seeds-status'),
      'Seed sweep failed: seeds 9007199254740990 to 9007199254740993 (4 from 9007199254740990): past the largest seed, 9007199254740991 (2^53 − 1); start at 9007199254740988 at most',
    );
    assert.equal(await page.locator('#seeds-plots .plot canvas').count(), 0);
  }));

const mapDone = (page) =>
  page
    .waitForFunction(() => ['done', 'failed', 'cancelled', 'refused'].includes(document.body.dataset.map), null, {
      timeout: 120_000,
    })
    .then(() => page.evaluate(() => document.body.dataset.map));

test("a model-error map link replays the map, its CSV is imlab robust's byte for byte, runaway cells are marked and never coloured, and a cell opens its run", async () => {
  const text = 'plant.rr=-10%..+10%:5;model.j=-20%..+20%:3;seeds=1..3';
  await withPage(`?v=1&preset=step#robust=${encodeURIComponent(text)}`, async (page) => {
    assert.equal(await mapDone(page), 'done');
    const csv = await download(page, '#map-csv');
    const native = execFileSync(
      cli,
      [
        'robust',
        'v=1&preset=step',
        '--vary',
        'plant.rr=-10%..+10%:5',
        '--vary',
        'model.j=-20%..+20%:3',
        '--seeds',
        '1..3',
      ],
      { stdio: ['ignore', 'pipe', 'ignore'] },
    ).toString();
    assert.equal(csv, native);
    // The CSV's runaway counts are what the cells show; a runaway cell carries no colour.
    const rows = native
      .trim()
      .split('\n')
      .slice(2)
      .map((l) => l.split(','));
    const cells = await page.$$eval('.map-table .map-cell', (bs) =>
      bs.map((b) => ({
        text: b.textContent,
        ranAway: b.classList.contains('map-ran-away'),
        background: b.style.background,
      })),
    );
    assert.equal(cells.length, rows.length);
    rows.forEach((r, i) => {
      const ranAway = Number(r[5]);
      assert.equal(cells[i].ranAway, ranAway > 0, `cell ${i}`);
      if (ranAway > 0)
        assert.ok(
          cells[i].text.startsWith(`✕ ${ranAway}/3`) && cells[i].background === '',
          `cell ${i}: ${cells[i].text}`,
        );
    });
    assert.ok(cells.some((c) => c.ranAway) && cells.some((c) => !c.ranAway), 'the map has both kinds of cell');
    // A click on the first cell runs its scenario, the one the CSV's row names.
    assert.equal(await startRun(page, () => page.click('.map-table .map-cell >> nth=0')), 'done');
    assert.equal(new URL(page.url()).search.slice(1), rows[0].at(-1));
  });
});

test("a gain is a map's axis in the page as in imlab robust, named in the page's language", async () => {
  const text = 'k1=-20%..+20%:3;seeds=1..2';
  const scenario = 'v=1&preset=step&duration=0.02';
  await withPage(`?${scenario}#lang=de&robust=${encodeURIComponent(text)}`, async (page) => {
    assert.equal(await mapDone(page), 'done');
    const csv = await download(page, '#map-csv');
    const native = execFileSync(cli, ['robust', scenario, '--vary', 'k1=-20%..+20%:3', '--seeds', '1..2'], {
      stdio: ['ignore', 'pipe', 'ignore'],
    }).toString();
    assert.equal(csv, native);
    assert.match(native.split('\n')[1], /^k1,k1_vs_base_pct,/);
    assert.match(await page.textContent('#map-plot'), /k1 gegenüber dem Basiswert \(%\)/);
  });
  // Under IFOC the backstepping gains act on nothing: the map is refused before any run.
  await withPage('?v=1&preset=ifoc-step&duration=0.02', async (page) => {
    await page.click('#tab-analysis');
    await page.fill('[name=axis1]', 'k1=-20%..+20%:3');
    await page.click('#map-run');
    assert.equal(await mapDone(page), 'refused');
    assert.match(await page.textContent('#map-status'), /k1 has no effect in this scenario/);
  });
});

test('a map past the work bound is refused before any run, naming what it needs; a cancelled map keeps its finished cells at once', async () => {
  await withPage('?v=1&preset=rr-mismatch&duration=20', async (page) => {
    await page.click('#tab-analysis');
    await page.fill('[name=axis1]', 'plant.rr=-10%..+10%:101');
    await page.fill('[name=seeds]', '1..100');
    await page.click('#map-run');
    assert.equal(await mapDone(page), 'refused');
    assert.match(await page.textContent('#map-status'), /needs 4040000000 plant steps/);
    await page.fill('[name=axis1]', 'plant.rr=-10%..+10%:21');
    await page.fill('[name=seeds]', '1..2');
    await page.click('#map-run');
    // Cancel once a cell (both its seeds) is in.
    await page.waitForFunction(() => Number(document.body.dataset.mapCells) >= 1, null, { timeout: 120_000 });
    // Cancel ends the workers that run the cells; the summary of the finished ones must not wait
    // for fresh workers to load the core.
    await page.evaluate(() => {
      window.workersMade = 0;
      window.Worker = class extends Worker {
        constructor(/** @type {any[]} */ ...args) {
          super(...args);
          window.workersMade++;
        }
      };
    });
    await page.click('#map-cancel');
    assert.equal(await mapDone(page), 'cancelled', await page.textContent('#map-status'));
    assert.equal(await page.evaluate(() => window.workersMade), 0, 'workers started after Cancel');
    const shown = await page.$$eval('.map-table .map-cell', (bs) => bs.length);
    const missing = await page.$$eval('.map-table .map-missing', (ts) => ts.length);
    assert.ok(shown >= 1 && shown + missing === 21, `${shown} shown, ${missing} not run`);
    assert.match(await page.textContent('#map-status'), new RegExp(`${shown} of 21 cells finished`));
    // The CSV holds the finished cells and says that the others did not run.
    const csv = await download(page, '#map-csv');
    assert.equal(csv.split('\n')[1], `# ${shown} of 21 cells: the map was stopped before the others ran`);
    assert.equal(csv.trim().split('\n').length, 3 + shown);
  });
});

test('a link with a sweep and a map runs both: neither cancels the other', async () => {
  const map = encodeURIComponent('plant.rr=-10%..+10%:3;seeds=1..2');
  await withPage(`?v=1&preset=step#sweep=50,400,3,0.02,0,0.2,euler&robust=${map}`, async (page) => {
    assert.equal(await mapDone(page), 'done');
    assert.equal(await sweepDone(page), 'done');
    assert.equal(await page.$$eval('.map-table .map-cell', (bs) => bs.length), 3);
  });
});

test("a motor typed as its nameplate and lab tests gives `imlab motor`'s circuit and link, runs them, and a bad reading is named", () =>
  withPage('?v=1&preset=step&duration=0.02', async (page) => {
    await page.click('[role=tab][data-tab=analysis]');
    await page.click('#motor-section > summary');
    await page.waitForSelector('#motor-section[data-built]');
    await page.click('#motor-example');
    await page.waitForFunction(() => document.querySelector('#motor-form [name=rs]').value !== '');
    const form = await page.evaluate(() =>
      Object.fromEntries([...new FormData(document.querySelector('#motor-form'))].map(([k, v]) => [k, String(v)])),
    );
    const printed = execFileSync(cli, [
      'motor',
      ...['rs', 'no_load', 'locked', 'nema', 'rated', 'j', 'np'].flatMap((k) => [`--${k.replace('_', '-')}`, form[k]]),
    ])
      .toString()
      .trim()
      .split('\n');
    await page.click('#motor-run');
    await page.waitForFunction(() => document.body.dataset.motor === 'done');
    // The heading, each value with how it was found, and the link, as the CLI prints them.
    assert.equal(await page.textContent('#motor-status'), printed[0].replace(/^# /, ''));
    const lines = await page.$$eval('#motor-result dt', (dts) =>
      dts.map((dt) => [dt.textContent, /** @type {HTMLElement} */ (dt.nextElementSibling).textContent]),
    );
    const collapse = (/** @type {string} */ text) => text.replace(/\s+/g, ' ').trim();
    assert.deepEqual(
      lines.map(([value, how]) => collapse(`${value} ${how}`)),
      printed.slice(1, 8).map(collapse),
    );
    const link = printed.at(-1);
    assert.equal(await page.textContent('#motor-result .motor-link'), link);
    await startRun(page, () => page.click('#motor-result button'));
    assert.equal(await page.evaluate(() => document.body.dataset.scenario), link);
    // A reading with a number missing is refused, naming the test.
    await page.click('[role=tab][data-tab=analysis]');
    await page.fill('#motor-form [name=no_load]', '400,2.985,98.9');
    await page.click('#motor-run');
    await page.waitForFunction(() => document.body.dataset.motor === 'refused');
    assert.equal(await page.locator('#motor-result > *').count(), 0);
    assert.match(await page.textContent('#motor-status'), /'no-load' = '400,2\.985,98\.9': expected V,I,P,F/);
  }));
