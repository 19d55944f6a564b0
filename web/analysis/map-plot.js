// The model-error map over one axis as a plot: the median of the chosen figure over the seeds and
// its min–max band, with the cells where a seed ran away left out and named below.
import uPlot from '../../vendor/uPlot.esm.js';
import { el } from '../ui/dom.js';
import { fmt } from './map-colours.js';
import { pageNumbers } from '../plots/numbers.js';
import { axisFont } from '../plots/options.js';
import { t } from '../l10n/l10n.js';
import { integer } from './digits.js';

/** @typedef {import('./robust.js').MapCell} MapCell */

/**
 * Appends the plot of `view` (see `mapView`) to `box`, and the cells it leaves out; its text and
 * lines `scale` times their normal size, as the trajectory plots' (presentation mode). Returns its
 * chart.
 * @param {HTMLElement} box
 * @param {import('./map-view.js').MapView} view
 * @param {number} scale
 */
export function bandPlot(box, view, scale) {
  const { axes, axisValue, axisName, byIndex, k, figure } = view;
  /**
   * @param {MapCell | undefined} cell
   * @returns {cell is MapCell}
   */
  const clean = (cell) => cell !== undefined && cell.ran_away === 0;
  // The band and median over the seeds of the cells where no seed ran away; the others are
  // gaps, marked below the plot and in the table, never drawn as values.
  const x = axes[0].values.map((_, i) => axisValue(0, i));
  const series = [0, 1, 2].map((s) =>
    axes[0].values.map((_, i) =>
      clean(byIndex[i]) && Number.isFinite(byIndex[i].stats[k][s]) ? byIndex[i].stats[k][s] : null,
    ),
  );
  const width = Math.max(320, box.clientWidth - 10);
  /** @type {uPlot.Options} */
  const opts = {
    title: t('map-plot-title', { figure: figure.label }),
    width,
    height: 280,
    scales: { x: { time: false } },
    series: [
      { label: axisName(0) },
      { label: t('map-series-min'), stroke: '#6baed6', width: scale },
      { label: t('map-series-median'), stroke: '#08519c', width: 2 * scale, points: { show: true } },
      { label: t('map-series-max'), stroke: '#6baed6', width: scale },
    ],
    bands: [{ series: /** @type {uPlot.Band.Bounds} */ ([3, 1]), fill: 'rgba(107,174,214,0.25)' }],
    axes: [
      { label: axisName(0), ...axisFont(scale), size: 50 * scale },
      { label: figure.unit || figure.label, ...axisFont(scale), size: 80 * scale },
    ],
  };
  const div = el('div', { className: 'plot' });
  div.dataset.plot = 'map';
  box.append(div);
  const chart = new uPlot(pageNumbers(opts), [x, series[0], series[1], series[2]], div);
  const gaps = axes[0].values.map((_, i) => i).filter((i) => byIndex[i] && byIndex[i].ran_away > 0);
  if (gaps.length) {
    const named = gaps.map((i) => {
      const cell = /** @type {MapCell} */ (byIndex[i]); // a gap is a cell that ran
      return t(axes[0].relative ? 'map-gap-percent' : 'map-gap', {
        value: fmt(axisValue(0, i)),
        ranAway: integer(cell.ran_away),
        runs: integer(cell.runs),
      });
    });
    box.append(el('p', { className: 'map-gaps', textContent: t('map-gaps', { cells: named.join(', ') }) }));
  }
  return chart;
}
