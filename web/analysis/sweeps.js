// The Analysis tab's frequency-response sweeps from their form, their progress and status line,
// and their CSV download; the seed runs beside them (seeds.js). A link's sweep (`#sweep=`) runs once.
import { $ } from '../ui/page.js';
import { formatSweep, isCount, parseSweep } from './analysis.js';
import { download } from '../ui/dom.js';
import { setFragment } from '../ui/url.js';
import { runFromLink } from './from-link.js';
import { createSeeds } from './seeds.js';

/** `analysis` runs the jobs and draws their results; `showTab(name)` opens a tab. */
export function createSweeps({ state, analysis, framing, showTab }) {
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

  /** After a run: a shared link with a sweep in its fragment runs that sweep, once. */
  const afterRun = runFromLink({
    name: 'sweep',
    what: 'sweep',
    fill: (text) => fillSweepForm(parseSweep(text)),
    run: runSweep,
    showTab,
  });

  $('sweep-run').addEventListener('click', runSweep);
  $('sweep-cancel').addEventListener('click', () => analysis.pool.cancel());
  $('sweep-csv').addEventListener('click', async () => {
    const first = Object.keys(analysis.points)[0];
    download(new Blob([await analysis.sweepCsv(first)], { type: 'text/csv' }), `imlab-sweep-${first}.csv`);
  });
  createSeeds({ state, analysis, framing });

  return { afterRun };
}
