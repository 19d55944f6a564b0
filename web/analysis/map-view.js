// The model-error map as drawn: the chosen figure of the cells that ran, each in its place in the
// full grid, as a plot (one axis) and a table.
import { el } from '../ui/dom.js';
import { bandPlot } from './map-plot.js';
import { figureName, mapTable } from './map-table.js';

/** @typedef {import('./robust.js').MapCell} MapCell */
/** @typedef {import('./robust.js').MapFigure} MapFigure */

/**
 * What the plot and the table draw of a map: its axes, the value of place `i` on axis `a` (in
 * per cent for a relative axis) and the axis's name, the cells by their place in the full grid
 * (undefined where a cell was not run), the chosen figure `k`, a cell's median of it, and the seeds.
 * @typedef {{axes: import('./robust.js').MapAxis[], axisValue: (a: number, i: number) => number,
 *   axisName: (a: number) => string, byIndex: (MapCell | undefined)[], k: number, figure: MapFigure,
 *   median: (cell: MapCell) => number, seeds: number[]}} MapView
 */

/**
 * What the plot and the table draw of `drawn` ({full, cells, figures, whole}: the map asked for,
 * the cells that finished, the figures a cell has, and which cells of the full grid finished),
 * for figure `k`.
 * @param {import('./robust.js').Drawn} drawn
 * @param {number} k
 * @returns {MapView}
 */
function mapView({ full, cells, figures, whole }, k) {
  const axes = full.axes;
  // The cells by their place in the full grid; a cell not run is undefined.
  /** @type {(MapCell | undefined)[]} */
  const byIndex = [];
  let c = 0;
  whole.forEach((w, i) => {
    if (w) byIndex[i] = cells[c++];
  });
  return {
    axes,
    axisValue: (a, i) => (axes[a].relative ? 100 * axes[a].errors[i] : axes[a].values[i]),
    axisName: (a) => axes[a].label,
    byIndex,
    k,
    figure: figures[k],
    median: (cell) => cell.stats[k][1],
    seeds: full.seeds,
  };
}

/**
 * Draws the map `drawn` into `box` for figure `k`, its plot's text `scale` times its normal size;
 * `open(scenario)` runs a cell. Returns the map's plot (a map over one axis has one), or null.
 * @param {HTMLElement} box
 * @param {import('./robust.js').Drawn} drawn
 * @param {number} k
 * @param {(scenario: string) => void} open
 * @param {number} scale
 */
export function drawMap(box, drawn, k, open, scale) {
  const view = mapView(drawn, k);
  box.replaceChildren();
  const chart = view.axes.length === 1 ? bandPlot(box, view, scale) : null;
  box.append(mapTable(view, open));
  return chart;
}

/**
 * The figure `select` chooses, as its index in `figures`; fills the list the first time.
 * @param {HTMLSelectElement} select
 * @param {MapFigure[]} figures
 */
export function chosenFigure(select, figures) {
  if (!select.options.length) {
    for (const f of figures) select.append(el('option', { value: f.name, textContent: figureName(f) }));
  }
  return figures.findIndex((f) => f.name === select.value);
}
