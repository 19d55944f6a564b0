// The Analysis tab's model-error map: the current scenario over one or two motor or model
// parameters times the noise seeds, run cell by cell in the pool's workers. The core checks and
// bounds the map, runs each cell and summarises it; this module draws what it returns. A link's
// map (`#robust=`) runs once; a cancelled map keeps the cells it finished.
import uPlot from '../../vendor/uPlot.esm.js';
import { $, say } from '../ui/page.js';
import { Pool } from '../client/pool.js';
import { download } from '../run/export.js';
import { excerpt, fragment, setFragment } from '../ui/url.js';
import { el } from '../ui/dom.js';

/** A number for a cell or an axis tick: four significant digits. */
const fmt = (v) => (Number.isFinite(v) ? Number(v.toPrecision(4)).toString() : '—');

// Colours of the heat map: light to dark for values of one sign (readable in greyscale), and
// blue through white to red for values of both signs, white at zero.
const SCALE = ['#f7fbff', '#deebf7', '#c6dbef', '#9ecae1', '#6baed6', '#4292c6', '#2171b5', '#08519c', '#08306b'];
const DIVERGING = ['#2166ac', '#4393c3', '#92c5de', '#d1e5f0', '#f7f7f7', '#fddbc7', '#f4a582', '#d6604d', '#b2182b'];

/**
 * The colour of `v` among `values`: values of both signs on a scale centred at zero; values of
 * one sign on a log scale when they span more than a decade, else linear. Returns {of(v) →
 * [colour, light text], words: the scale and its ends}.
 */
function colourScale(values) {
  const finite = values.filter(Number.isFinite);
  const [min, max] = [Math.min(...finite), Math.max(...finite)];
  const pick = (palette, x) => {
    const i = Math.min(palette.length - 1, Math.max(0, Math.round(x * (palette.length - 1))));
    return [palette[i], palette === SCALE ? i >= 5 : i <= 1 || i >= 7];
  };
  if (min < 0 && max > 0) {
    const m = Math.max(-min, max);
    return { of: (v) => pick(DIVERGING, 0.5 + v / (2 * m)), words: `blue −${fmt(m)} through white 0 to red ${fmt(m)}` };
  }
  const log = min > 0 && max / min > 10;
  const f = log ? Math.log10 : (v) => v;
  const [lo, hi] = [f(min), f(max)];
  return {
    of: (v) => pick(SCALE, hi > lo ? (f(v) - lo) / (hi - lo) : 0.5),
    words: `${log ? 'log' : 'linear'} scale from light ${fmt(min)} to dark ${fmt(max)}`,
  };
}

/** `analysis` holds the worker pool; `open(scenario)` runs a scenario on the Plots tab. */
export function createRobust({ state, analysis, open, showTab }) {
  let shared = fragment('robust'); // from the link that opened the page
  let last = null; // {map, full, cells, figures, whole}: the map drawn
  // The map's own workers: a sweep or a seed run on the Analysis tab's other pool neither waits
  // for it nor cancels it.
  const pool = new Pool(analysis.pool.size);
  const form = $('map-form');
  const status = $('map-status');
  const progress = $('map-progress');

  function fill(text) {
    const parts = text
      .split(';')
      .map((p) => p.trim())
      .filter(Boolean);
    const seeds = parts.find((p) => p.startsWith('seeds='));
    const axes = parts.filter((p) => !p.startsWith('seeds='));
    form.elements.namedItem('axis1').value = axes[0] ?? '';
    // A third axis stays in the form, where the core refuses it by name.
    form.elements.namedItem('axis2').value = axes.slice(1).join(';');
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
      [plan] = await pool.run([{ kind: 'map-plan', scenario: state.info.encoded, text }]);
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
    const finished = new Array(map.cells.length).fill(0);
    let cellsDone = 0;
    $('map-run').disabled = true;
    $('map-cancel').disabled = false;
    $('map-csv').disabled = true;
    progress.value = 0;
    Object.assign(document.body.dataset, { map: 'running', mapCells: '0' });
    status.textContent = `Running ${map.cells.length} cells × ${per} seeds…`;
    const started = performance.now();
    let cancelled = false;
    try {
      const jobs = map.cells.flatMap((c) => map.seeds.map((seed) => ({ kind: 'map-run', scenario: c.scenario, seed })));
      await pool.run(jobs, (done, index, result) => {
        runs[index] = result;
        if (++finished[Math.floor(index / per)] === per) document.body.dataset.mapCells = String(++cellsDone);
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
    // The cells whose every seed finished (all of them unless cancelled); the summary that
    // follows cannot be cancelled, so that what finished is kept.
    $('map-cancel').disabled = true;
    const whole = finished.map((n) => n === per);
    const kept = { ...map, cells: map.cells.filter((_, i) => whole[i]) };
    try {
      const [cells] = await pool.run([
        { kind: 'map-cells', map: kept, runs: runs.filter((_, i) => whole[Math.floor(i / per)]) },
      ]);
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
      for (const f of last.figures)
        select.append(el('option', { value: f.name, textContent: f.unit ? `${f.label} (${f.unit})` : f.label }));
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
    const relative = axes.map((a) => a.relative);
    const axisValue = (a, i) => (relative[a] ? 100 * axes[a].errors[i] : axes[a].values[i]);
    const axisName = (a) => axes[a].label;
    // The cells by their place in the full grid; a cell not run is undefined.
    const byIndex = [];
    let c = 0;
    whole.forEach((w, i) => {
      if (w) byIndex[i] = cells[c++];
    });
    const median = (cell) => cell.stats[k][1];
    const clean = (cell) => cell && cell.ran_away === 0;
    if (axes.length === 1) {
      // The band and median over the seeds of the cells where no seed ran away; the others are
      // gaps, marked below the plot and in the table, never drawn as values.
      const x = axes[0].values.map((_, i) => axisValue(0, i));
      const series = [0, 1, 2].map((s) =>
        axes[0].values.map((_, i) =>
          clean(byIndex[i]) && Number.isFinite(byIndex[i].stats[k][s]) ? byIndex[i].stats[k][s] : null,
        ),
      );
      const width = Math.max(320, box.clientWidth - 10);
      const opts = {
        title: `${figure.label} over the seeds: median, and min–max band`,
        width,
        height: 280,
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
        box.append(
          el('p', {
            className: 'map-gaps',
            textContent: `Not drawn, because some seeds ran away there: ${gaps.map((i) => `${fmt(axisValue(0, i))}${relative[0] ? ' %' : ''} (${byIndex[i].ran_away} of ${byIndex[i].runs} seeds)`).join(', ')}.`,
          }),
        );
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
      else if (Number.isFinite(median(cell))) {
        // A cell whose runs lack the figure (the IFOC has no NIS) stays uncoloured, shown as —.
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
      t.append(
        el(
          'tr',
          {},
          [axisName(0), 'median', 'min – max'].map((h) => el('th', { scope: 'col', textContent: h })),
        ),
      );
      axes[0].values.forEach((_, i) => {
        const cell = byIndex[i];
        const range = cell && cell.ran_away === 0 ? `${fmt(cell.stats[k][0])} – ${fmt(cell.stats[k][2])}` : '';
        t.append(
          el('tr', {}, [
            el('th', { scope: 'row', textContent: fmt(axisValue(0, i)) }),
            cellOf(cell),
            el('td', { className: 'map-range', textContent: range }),
          ]),
        );
      });
    }
    const key = el('p', {
      className: 'map-key',
      textContent: `${figure.label}${figure.unit ? ` (${figure.unit})` : ''}, median over the seeds that did not run away (${last.full.seeds.length} seeds); colour: ${values.length ? scale.words : 'none'}. ✕ k/N: the run ran away on k of the N seeds (the run's own page says so, or it diverged), never coloured as a value; ⚠ the EKF was inconsistent. Click a cell to run it (seed ${last.full.seeds[0]}).`,
    });
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
  $('map-cancel').addEventListener('click', () => pool.cancel());
  $('map-figure').addEventListener('change', () => last && draw());
  $('map-csv').addEventListener('click', async () => {
    const [csv] = await pool.run([{ kind: 'map-csv', map: last.full, cells: last.cells }]);
    download(new Blob([csv], { type: 'text/csv' }), 'imlab-robust.csv');
  });

  return { afterRun, fill };
}
