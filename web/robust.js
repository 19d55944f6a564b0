// The Analysis tab's model-error map: the current scenario over one or two motor or model
// parameters times the noise seeds, run cell by cell in the pool's workers. The core checks and
// bounds the map, runs each cell and summarises it; this module draws what it returns. A link's
// map (`#robust=`) runs once; a cancelled map keeps the cells it finished.
import uPlot from '../vendor/uPlot.esm.js';
import { $, say } from './page.js';
import { download } from './export.js';
import { excerpt, fragment, setFragment } from './url.js';

const el = (tag, props = {}, children = []) => {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...children);
  return e;
};

/** A number for a cell or an axis tick: four significant digits. */
const fmt = (v) => (Number.isFinite(v) ? Number(v.toPrecision(4)).toString() : '—');

// Colours of the heat map, light to dark (a sequential scale readable in greyscale).
const SCALE = ['#f7fbff', '#deebf7', '#c6dbef', '#9ecae1', '#6baed6', '#4292c6', '#2171b5', '#08519c', '#08306b'];

/**
 * The colour of `v` among `values`: on a log scale when they are all positive and span more
 * than a decade, else linear. Returns [colour, whether the text on it should be light].
 */
function colourScale(values) {
  const finite = values.filter(Number.isFinite);
  const log = finite.length > 0 && finite.every((v) => v > 0) && Math.max(...finite) / Math.min(...finite) > 10;
  const f = log ? Math.log10 : (v) => v;
  const [lo, hi] = [Math.min(...finite.map(f)), Math.max(...finite.map(f))];
  return {
    log,
    of: (v) => {
      const x = hi > lo ? (f(v) - lo) / (hi - lo) : 0.5;
      const i = Math.min(SCALE.length - 1, Math.max(0, Math.round(x * (SCALE.length - 1))));
      return [SCALE[i], i >= 5];
    },
  };
}

/** `analysis` holds the worker pool; `open(scenario)` runs a scenario on the Plots tab. */
export function createRobust({ state, analysis, open, showTab }) {
  let shared = fragment('robust'); // from the link that opened the page
  let last = null; // {map, cells, figures, partial}: the map drawn
  const form = $('map-form');
  const status = $('map-status');
  const progress = $('map-progress');

  function fill(text) {
    const parts = text.split(';').map((p) => p.trim()).filter(Boolean);
    const seeds = parts.find((p) => p.startsWith('seeds='));
    const axes = parts.filter((p) => !p.startsWith('seeds='));
    form.elements.namedItem('axis1').value = axes[0] ?? '';
    form.elements.namedItem('axis2').value = axes[1] ?? '';
    if (seeds) form.elements.namedItem('seeds').value = seeds.slice('seeds='.length);
  }

  function formText() {
    const f = form.elements;
    const axes = ['axis1', 'axis2'].map((n) => f.namedItem(n).value.trim()).filter(Boolean);
    return [...axes, `seeds=${f.namedItem('seeds').value.trim()}`].join(';');
  }

  async function runMap() {
    const text = formText();
    let plan;
    try {
      [plan] = await analysis.pool.run([{ kind: 'map-plan', scenario: state.info.encoded, text }]);
    } catch (e) {
      status.textContent = `The map was not run: ${e.message}.`;
      document.body.dataset.map = 'refused';
      return;
    }
    const { map, figures } = plan;
    setFragment('robust', encodeURIComponent(map.text));
    const per = map.seeds.length;
    const total = map.cells.length * per;
    const runs = new Array(total);
    $('map-run').disabled = true;
    $('map-cancel').disabled = false;
    $('map-csv').disabled = true;
    progress.value = 0;
    document.body.dataset.map = 'running';
    status.textContent = `Running ${map.cells.length} cells × ${per} seeds…`;
    const started = performance.now();
    let cancelled = false;
    try {
      const jobs = map.cells.flatMap((c) => map.seeds.map((seed) => ({ kind: 'map-run', scenario: c.scenario, seed })));
      await analysis.pool.run(jobs, (done, index, result) => {
        runs[index] = result;
        progress.value = done / total;
        status.textContent = `Running the map: ${done} of ${total} runs.`;
      });
    } catch (e) {
      if (e.message !== 'cancelled') {
        status.textContent = `The map failed: ${e.message}`;
        document.body.dataset.map = 'failed';
        $('map-run').disabled = false;
        $('map-cancel').disabled = true;
        return;
      }
      cancelled = true;
    }
    // The cells whose every seed finished (all of them unless cancelled).
    const whole = map.cells.map((_, i) => runs.slice(i * per, (i + 1) * per).filter(Boolean).length === per);
    const kept = { ...map, cells: map.cells.filter((_, i) => whole[i]) };
    try {
      const [cells] = await analysis.pool.run([{ kind: 'map-cells', map: kept, runs: runs.filter((_, i) => whole[Math.floor(i / per)]) }]);
      last = { map: kept, full: map, cells, figures, whole };
      draw();
      const ms = performance.now() - started;
      status.textContent = cancelled
        ? `Map cancelled: ${cells.length} of ${map.cells.length} cells finished and are shown; the others were not run.`
        : `${map.cells.length} cells × ${per} seeds (${map.seeds[0]}–${map.seeds.at(-1)}) in ${(ms / 1000).toFixed(1)} s.`;
      document.body.dataset.map = cancelled ? 'cancelled' : 'done';
      $('map-csv').disabled = cells.length === 0;
    } catch (e) {
      status.textContent = `The map failed: ${e.message}`;
      document.body.dataset.map = 'failed';
    } finally {
      $('map-run').disabled = false;
      $('map-cancel').disabled = true;
    }
  }

  /** The figure chosen to draw, by its name. */
  function chosen() {
    const select = $('map-figure');
    if (!select.options.length) {
      for (const f of last.figures) select.append(el('option', { value: f.name, textContent: f.unit ? `${f.label} (${f.unit})` : f.label }));
    }
    return last.figures.findIndex((f) => f.name === select.value);
  }

  function draw() {
    $('map-figure-label').hidden = false;
    const k = chosen();
    const figure = last.figures[k];
    const box = $('map-plot');
    box.replaceChildren();
    const { full, cells, whole } = last;
    const axes = full.axes;
    const relative = axes.map((a) => a.text.includes('%'));
    const axisValue = (a, i) => (relative[a] ? 100 * axes[a].errors[i] : axes[a].values[i]);
    const axisName = (a) => (relative[a] ? `${axes[a].key} against the ${axes[a].key.startsWith('plant.') ? 'model' : 'motor'} (%)` : axes[a].key);
    // The cells by their place in the full grid; a cell not run is undefined.
    const byIndex = [];
    let c = 0;
    whole.forEach((w, i) => { if (w) byIndex[i] = cells[c++]; });
    const median = (cell) => cell.stats[k][1];
    const clean = (cell) => cell && cell.ran_away === 0;
    if (axes.length === 1) {
      // The band and median over the seeds of the cells where no seed ran away; the others are
      // gaps, marked below the plot and in the table, never drawn as values.
      const x = axes[0].values.map((_, i) => axisValue(0, i));
      const series = [0, 1, 2].map((s) => axes[0].values.map((_, i) => (clean(byIndex[i]) ? byIndex[i].stats[k][s] : null)));
      const width = Math.max(320, box.clientWidth - 10);
      const opts = {
        title: `${figure.label} over the seeds: median, and min–max band`,
        width, height: 280,
        scales: { x: { time: false } },
        series: [
          { label: axisName(0) },
          { label: 'min', stroke: '#6baed6', width: 1 },
          { label: 'median', stroke: '#08519c', width: 2, points: { show: true } },
          { label: 'max', stroke: '#6baed6', width: 1 },
        ],
        bands: [{ series: [3, 1], fill: 'rgba(107,174,214,0.25)' }],
        axes: [{ label: axisName(0) }, { label: figure.unit || figure.label, size: 70 }],
      };
      const div = el('div', { className: 'plot' });
      box.append(div);
      new uPlot(opts, [x, series[0], series[1], series[2]], div);
      const gaps = axes[0].values.map((_, i) => i).filter((i) => byIndex[i] && byIndex[i].ran_away > 0);
      if (gaps.length) {
        box.append(el('p', { className: 'map-gaps', textContent: `Not drawn, because some seeds ran away there: ${gaps.map((i) => `${fmt(axisValue(0, i))}${relative[0] ? ' %' : ''} (${byIndex[i].ran_away} of ${byIndex[i].runs} seeds)`).join(', ')}.` }));
      }
    }
    box.append(table(axes, axisValue, axisName, byIndex, median, figure));
  }

  /**
   * The map as a table of buttons, coloured by the figure's median; a click opens the cell's run.
   * One axis is a column (a row a value, with the range over the seeds); two are a grid.
   */
  function table(axes, axisValue, axisName, byIndex, median, figure) {
    const two = axes.length === 2;
    const k = chosen();
    const values = byIndex.filter((cell) => cell && cell.ran_away === 0).map(median);
    const scale = colourScale(values);
    const cellOf = (cell) => {
      const td = el('td');
      if (!cell) {
        td.textContent = 'not run';
        td.className = 'map-missing';
        return td;
      }
      const lines = [cell.ran_away > 0 ? `✕ ${cell.ran_away}/${cell.runs}` : fmt(median(cell))];
      if (cell.inconsistent > 0) lines.push(`⚠ ${cell.inconsistent}/${cell.runs}`);
      const button = el('button', { type: 'button', className: 'map-cell', textContent: lines.join(' ') });
      button.title = `${cell.scenario}: ${cell.ran_away} of ${cell.runs} seeds ran away, ${cell.inconsistent} inconsistent; ${figure.label} ${fmt(cell.stats[k][0])} to ${fmt(cell.stats[k][2])}`;
      if (cell.ran_away > 0) button.classList.add('map-ran-away');
      else {
        const [colour, light] = scale.of(median(cell));
        Object.assign(button.style, { background: colour, color: light ? '#fff' : '#000' });
      }
      button.addEventListener('click', () => open(cell.scenario));
      td.append(button);
      return td;
    };
    const t = el('table', { className: 'map-table' });
    if (two) {
      const [rows, cols] = [axes[0].values.length, axes[1].values.length];
      const head = el('tr', {}, [el('th', { scope: 'col', textContent: `${axisName(0)} ↓ / ${axisName(1)} →` })]);
      for (let j = 0; j < cols; j++) head.append(el('th', { scope: 'col', textContent: fmt(axisValue(1, j)) }));
      t.append(head);
      for (let i = 0; i < rows; i++) {
        const tr = el('tr', {}, [el('th', { scope: 'row', textContent: fmt(axisValue(0, i)) })]);
        for (let j = 0; j < cols; j++) tr.append(cellOf(byIndex[i * cols + j]));
        t.append(tr);
      }
    } else {
      t.append(el('tr', {}, [axisName(0), 'median', 'min – max'].map((h) => el('th', { scope: 'col', textContent: h }))));
      axes[0].values.forEach((_, i) => {
        const cell = byIndex[i];
        const range = cell && cell.ran_away === 0 ? `${fmt(cell.stats[k][0])} – ${fmt(cell.stats[k][2])}` : '';
        t.append(el('tr', {}, [el('th', { scope: 'row', textContent: fmt(axisValue(0, i)) }), cellOf(cell), el('td', { className: 'map-range', textContent: range })]));
      });
    }
    const key = el('p', { className: 'map-key', textContent: `${figure.label}${figure.unit ? ` (${figure.unit})` : ''}, median over ${last.full.seeds.length} seeds; colour on a ${scale.log ? 'log' : 'linear'} scale; ✕ ran away on that many seeds (never coloured as a value); ⚠ EKF inconsistent. Click a cell to run it (seed ${last.full.seeds[0]}).` });
    return el('div', {}, [key, t]);
  }

  /** After a run: a shared link with a map in its fragment runs that map, once. */
  function afterRun() {
    const text = shared;
    shared = null;
    if (text) {
      try {
        fill(decodeURIComponent(text));
        showTab('analysis');
        runMap();
      } catch (e) {
        say(`The map in the address (#robust=${excerpt(text)}) was not run: ${e.message}.`);
      }
    }
  }

  $('map-run').addEventListener('click', runMap);
  $('map-cancel').addEventListener('click', () => analysis.pool.cancel());
  $('map-figure').addEventListener('change', () => last && draw());
  $('map-csv').addEventListener('click', async () => {
    const [csv] = await analysis.pool.run([{ kind: 'map-csv', map: last.map, cells: last.cells }]);
    download(new Blob([csv], { type: 'text/csv' }), 'imlab-robust.csv');
  });

  return { afterRun, fill };
}
