// The model-error map as a table of buttons, coloured by the chosen figure's median over the
// seeds; a click opens the cell's run. One axis is a column (a row a value, with the range over
// the seeds); two are a grid.
import { el } from '../ui/dom.js';
import { colourScale, fmt } from './map-colours.js';
import { t } from '../l10n/l10n.js';
import { integer } from './digits.js';

/** @typedef {import('./robust.js').MapCell} MapCell */
/** @typedef {import('./robust.js').MapFigure} MapFigure */
/** @typedef {import('./map-view.js').MapView} MapView */

/**
 * A figure's name as the map writes it: its label, and its unit if it has one.
 * @param {MapFigure} figure
 */
export const figureName = (figure) =>
  figure.unit ? t('map-figure-unit', { figure: figure.label, unit: figure.unit }) : figure.label;

/**
 * The cell of one map cell: a button that opens its run, or 'not run'.
 * @param {MapCell | undefined} cell
 * @param {MapView} view
 * @param {import('./map-colours.js').ColourScale} scale
 * @param {(scenario: string) => void} open
 */
function cellOf(cell, view, scale, open) {
  const { k, figure, median } = view;
  const td = el('td');
  if (!cell) {
    td.textContent = t('map-cell-not-run');
    td.className = 'map-missing';
    return td;
  }
  const lines = [cell.ran_away > 0 ? `✕ ${cell.ran_away}/${cell.runs}` : fmt(median(cell))];
  if (cell.inconsistent > 0) lines.push(`⚠ ${cell.inconsistent}/${cell.runs}`);
  // What holding cost, on the seeds that did not run away: past the rating, or not settled.
  const held = cell.runs - cell.ran_away;
  if (cell.over_rating > 0) lines.push(`I↑ ${cell.over_rating}/${held}`);
  if (cell.unsettled > 0) lines.push(`~ ${cell.unsettled}/${held}`);
  const button = el('button', { type: 'button', className: 'map-cell', textContent: lines.join(' ') });
  button.title = t('map-cell-title', {
    scenario: cell.scenario,
    ranAway: integer(cell.ran_away),
    runs: integer(cell.runs),
    inconsistent: integer(cell.inconsistent),
    overRating: integer(cell.over_rating),
    unsettled: integer(cell.unsettled),
    figure: figure.label,
    min: fmt(cell.stats[k][0]),
    max: fmt(cell.stats[k][2]),
  });
  if (cell.over_rating > 0 || cell.unsettled > 0) button.classList.add('map-costly');
  if (cell.ran_away > 0) button.classList.add('map-ran-away');
  else if (Number.isFinite(median(cell))) {
    // A cell whose runs lack the figure (the IFOC has no NIS) stays uncoloured, shown as —.
    const [colour, light] = scale.of(median(cell));
    Object.assign(button.style, { background: colour, color: light ? '#fff' : '#000' });
  }
  button.addEventListener('click', () => open(cell.scenario));
  td.append(button);
  return td;
}

/**
 * The rows of a two-axis map: the first axis down, the second across.
 * @param {MapView} view
 * @param {(cell: MapCell | undefined) => HTMLElement} cell
 */
function gridRows(view, cell) {
  const { axes, axisValue, axisName, byIndex } = view;
  const [rows, cols] = [axes[0].values.length, axes[1].values.length];
  const corner = t('map-grid-corner', { rows: axisName(0), columns: axisName(1) });
  const head = el('tr', {}, [el('th', { scope: 'col', textContent: corner })]);
  for (let j = 0; j < cols; j++) head.append(el('th', { scope: 'col', textContent: fmt(axisValue(1, j)) }));
  const trs = [head];
  for (let i = 0; i < rows; i++) {
    const tr = el('tr', {}, [el('th', { scope: 'row', textContent: fmt(axisValue(0, i)) })]);
    for (let j = 0; j < cols; j++) tr.append(cell(byIndex[i * cols + j]));
    trs.push(tr);
  }
  return trs;
}

/**
 * The rows of a one-axis map: a value a row, its cell and its range over the seeds.
 * @param {MapView} view
 * @param {(cell: MapCell | undefined) => HTMLElement} cell
 */
function columnRows(view, cell) {
  const { axes, axisValue, axisName, byIndex, k } = view;
  const head = el(
    'tr',
    {},
    [axisName(0), t('map-head-median'), t('map-head-range')].map((h) => el('th', { scope: 'col', textContent: h })),
  );
  return [
    head,
    ...axes[0].values.map((_, i) => {
      const c = byIndex[i];
      const range = c && c.ran_away === 0 ? t('map-range', { min: fmt(c.stats[k][0]), max: fmt(c.stats[k][2]) }) : '';
      return el('tr', {}, [
        el('th', { scope: 'row', textContent: fmt(axisValue(0, i)) }),
        cell(c),
        el('td', { className: 'map-range', textContent: range }),
      ]);
    }),
  ];
}

/**
 * The table of `view` (see `mapView`) and its key; `open(scenario)` runs a cell's scenario.
 * @param {MapView} view
 * @param {(scenario: string) => void} open
 */
export function mapTable(view, open) {
  const { figure, median, seeds } = view;
  const ran = /** @type {MapCell[]} */ (view.byIndex.filter((cell) => cell && cell.ran_away === 0));
  const values = ran.map(median);
  const scale = colourScale(values);
  /** @param {MapCell | undefined} c */
  const cell = (c) => cellOf(c, view, scale, open);
  const table = el(
    'table',
    { className: 'map-table' },
    view.axes.length === 2 ? gridRows(view, cell) : columnRows(view, cell),
  );
  const key = el('p', {
    className: 'map-key',
    textContent: t('map-key', {
      figure: figureName(figure),
      seeds: integer(seeds.length),
      colours: values.length ? scale.words : t('map-scale-none'),
      seed: String(seeds[0]),
    }),
  });
  return el('div', {}, [key, table]);
}
