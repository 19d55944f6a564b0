// The model-error map as drawn: the chosen figure of the cells that ran, each in its place in the
// full grid, as a plot (one axis) and a table.
import { el } from '../ui/dom.js';
import { bandPlot } from './map-plot.js';
import { mapTable } from './map-table.js';

/**
 * What the plot and the table draw of `drawn` ({full, cells, figures, whole}: the map asked for,
 * the cells that finished, the figures a cell has, and which cells of the full grid finished),
 * for figure `k`.
 */
function mapView({ full, cells, figures, whole }, k) {
  const axes = full.axes;
  // The cells by their place in the full grid; a cell not run is undefined.
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

/** Draws the map `drawn` into `box` for figure `k`; `open(scenario)` runs a cell. */
export function drawMap(box, drawn, k, open) {
  const view = mapView(drawn, k);
  box.replaceChildren();
  if (view.axes.length === 1) bandPlot(box, view);
  box.append(mapTable(view, open));
}

/** The figure `select` chooses, as its index in `figures`; fills the list the first time. */
export function chosenFigure(select, figures) {
  if (!select.options.length) {
    for (const f of figures)
      select.append(el('option', { value: f.name, textContent: f.unit ? `${f.label} (${f.unit})` : f.label }));
  }
  return figures.findIndex((f) => f.name === select.value);
}
