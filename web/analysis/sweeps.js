// The Analysis tab's runs: frequency-response sweeps and seed runs from their forms, their
// progress and status lines, and their CSV downloads. A link's sweep (`#sweep=`) runs once.
import { $, say } from '../ui/page.js';
import { formatSweep, isCount, parseSweep } from './analysis.js';
import { fieldValue } from '../run/controls.js';
import { download } from '../run/export.js';
import { excerpt, fragment, setFragment } from '../ui/url.js';

/** `analysis` runs the jobs and draws their results; `showTab(name)` opens a tab. */
export function createSweeps({ state, analysis, framing, showTab }) {
  let shared = fragment('sweep'); // from the link that opened the page
  let seedsCsv = null; // the last seed runs' CSV
  const sweepForm = $('sweep-form');
  sweepForm.elements.namedItem('workers').value = analysis.pool.size;

  function readSweepForm() {
    const f = sweepForm.elements;
    const num = (name) => Number(f.namedItem(name).value);
    return {
      lo: num('lo'),
      hi: num('hi'),
      n: num('n'),
      amp: num('amp'),
      offset: num('offset'),
      duration: num('duration'),
      variants: [...sweepForm.querySelectorAll('[name=variant]:checked')].map((c) => c.value),
      workers: num('workers'),
    };
  }

  function fillSweepForm(s) {
    for (const key of ['lo', 'hi', 'n', 'amp', 'offset', 'duration']) sweepForm.elements.namedItem(key).value = s[key];
    for (const c of sweepForm.querySelectorAll('[name=variant]')) c.checked = s.variants.includes(c.value);
  }

  async function runSweep() {
    const settings = readSweepForm();
    const status = $('sweep-status');
    if (!settings.variants.length) {
      status.textContent = 'Choose at least one variant.';
      return;
    }
    if (!isCount(settings.n)) {
      status.textContent = `points = ${sweepForm.elements.namedItem('n').value}: expected a whole number.`;
      return;
    }
    if (!(Number.isInteger(settings.workers) && settings.workers >= 1 && settings.workers <= 8)) {
      status.textContent = `workers = ${sweepForm.elements.namedItem('workers').value}: expected a whole number from 1 to 8.`;
      return;
    }
    setFragment('sweep', formatSweep(settings));
    $('sweep-run').disabled = true;
    $('sweep-cancel').disabled = false;
    const started = performance.now();
    status.textContent = 'Sweeping…';
    try {
      const out = await analysis.sweep(settings, {
        workers: settings.workers,
        onProgress: (p) => {
          $('sweep-progress').value = p;
        },
      });
      analysis.showSweep(out, $('bode'), $('sweep-table'));
      const ms = performance.now() - started;
      status.textContent = `${settings.variants.length} × ${settings.n} runs in ${ms.toFixed(0)} ms on ${settings.workers} worker${settings.workers > 1 ? 's' : ''}.`;
      if (settings.variants.some((v) => v.startsWith('ifoc')) && Math.abs(settings.offset) < 20) {
        status.textContent +=
          ' The IFOC figures are not meaningful here: its MRAS cannot estimate the speed near standstill. Sweep it about an operating speed (offset ≥ 20 rad/s) with longer runs (3 s).';
      }
      Object.assign(document.body.dataset, { sweep: 'done', sweepMs: ms.toFixed(1) });
      $('sweep-csv').disabled = false;
    } catch (e) {
      status.textContent = e.message === 'cancelled' ? 'Sweep cancelled.' : `Sweep failed: ${e.message}`;
      document.body.dataset.sweep = e.message === 'cancelled' ? 'cancelled' : 'failed';
    } finally {
      $('sweep-run').disabled = false;
      $('sweep-cancel').disabled = true;
    }
  }

  async function runSeeds() {
    const n = Number($('seeds-form').elements.namedItem('n').value);
    const status = $('seeds-status');
    if (!(Number.isInteger(n) && n >= 1 && n <= 1000)) {
      status.textContent = `seeds = ${$('seeds-form').elements.namedItem('n').value}: expected a whole number from 1 to 1000.`;
      return;
    }
    status.textContent = 'Running seeds…';
    const progress = $('seeds-progress');
    progress.value = 0;
    $('seeds-cancel').disabled = false;
    document.body.dataset.seeds = 'running';
    try {
      const first = Number(fieldValue(state.info, 'seed'));
      const out = await analysis.seeds(n, first, state.info.steps, (p) => {
        progress.value = p;
        status.textContent = `Running seeds: ${(p * 100).toFixed(0)} %`;
      });
      analysis.showSeeds(out, $('seeds-plots'), framing);
      seedsCsv = out.csv;
      $('seeds-csv').disabled = false;
      status.textContent = `${out.bands.runs} of ${n} seeds (${first} to ${first + n - 1}) completed.`;
      document.body.dataset.seeds = 'done';
    } catch (e) {
      const cancelled = e.message === 'cancelled';
      status.textContent = cancelled ? 'Seed runs cancelled.' : `Seed sweep failed: ${e.message}`;
      document.body.dataset.seeds = cancelled ? 'cancelled' : 'failed';
    } finally {
      $('seeds-cancel').disabled = true;
    }
  }

  /** After a run: a shared link with a sweep in its fragment runs that sweep, once. */
  function afterRun() {
    const sweep = shared;
    shared = null;
    if (sweep) {
      try {
        fillSweepForm(parseSweep(sweep));
        showTab('analysis');
        runSweep();
      } catch (e) {
        say(`The sweep in the address (#sweep=${excerpt(sweep)}) was not run: ${e.message}.`);
      }
    }
  }

  $('sweep-run').addEventListener('click', runSweep);
  $('sweep-cancel').addEventListener('click', () => analysis.pool.cancel());
  $('sweep-csv').addEventListener('click', async () => {
    const first = Object.keys(analysis.points)[0];
    download(new Blob([await analysis.sweepCsv(first)], { type: 'text/csv' }), `imlab-sweep-${first}.csv`);
  });
  $('seeds-run').addEventListener('click', runSeeds);
  $('seeds-cancel').addEventListener('click', () => analysis.pool.cancel());
  $('seeds-csv').addEventListener('click', () =>
    download(new Blob([seedsCsv], { type: 'text/csv' }), 'imlab-seeds.csv'),
  );

  return { afterRun };
}
