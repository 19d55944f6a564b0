// A chart's uPlot options: its series in the plots' colours, its axes and their ranges, and the
// hooks that tie it to its set (zoom, inspect, double-click for the whole run).
import { STYLE, CONSTANT } from './style.js';
import { STEPS, six, tickLabels, timeSpace } from './numbers.js';
import { fittedRange, logRange } from './ranges.js';
import { drawMarker, pickOnClick } from './inspect.js';

const SYNC_KEY = 'imlab-time';

/** @typedef {import('./plot-defs.js').PlotDef} PlotDef */

/**
 * The legend's series of `plot`: time, its signals, then its constant lines.
 * @param {PlotDef} plot
 * @param {number} lineWidth
 * @returns {uPlot.Series[]}
 */
function seriesOf(plot, lineWidth) {
  /** @type {uPlot.Series[]} */
  const series = [{ label: 't (s)', value: (u, v) => (v == null ? '–' : `${six(v)} s`) }];
  for (const [column, label, axis] of plot.series) {
    const style = STYLE[column] ?? { stroke: '#444' };
    series.push({
      label,
      scale: axis === 'y2' ? 'y2' : 'y',
      stroke: style.stroke,
      dash: style.dash,
      width: lineWidth,
      value: (u, v) => six(v),
    });
  }
  for (const [label, axis] of plot.constants ?? []) {
    series.push({ label, scale: axis ?? 'y', ...CONSTANT, width: lineWidth, value: (u, v) => six(v) });
  }
  return series;
}

/**
 * The text of a plot's axes, `k` times its normal size: its ticks' and its label's font and the
 * label's room. Every plot of the page uses it, so that a room reads them all alike.
 * @param {number} k
 */
export const axisFont = (k) => ({
  font: `${14 * k}px system-ui`,
  labelFont: `${14 * k}px system-ui`,
  labelSize: 24 * k,
});

/**
 * The time axis, the left y-axis and, for a plot with `unit2`, the right one; `k` scales the text.
 * @param {PlotDef} plot
 * @param {number} k
 * @returns {uPlot.Axis[]}
 */
function axesOf(plot, k) {
  const font = axisFont(k);
  /** @type {uPlot.Axis[]} */
  const axes = [
    { label: 't (s)', ...font, size: 50 * k, space: timeSpace(14 * k, 50 * k), incrs: STEPS, values: tickLabels },
    {
      label: plot.unit,
      scale: 'y',
      ...font,
      size: 80 * k,
      ...(plot.log ? {} : { incrs: STEPS }),
      values: tickLabels,
    },
  ];
  if (plot.unit2)
    axes.push({
      label: plot.unit2,
      scale: 'y2',
      side: 1,
      grid: { show: false },
      ...font,
      size: 80 * k,
      incrs: STEPS,
      values: tickLabels,
    });
  return axes;
}

/**
 * The options of the chart of `plot` in the set `set` (a Plots), `width` px wide.
 * @param {import('./plots.js').Plots} set
 * @param {PlotDef} plot
 * @param {number} width
 * @returns {uPlot.Options}
 */
export function chartOptions(set, plot, width) {
  /** @type {uPlot.Range.Function} */
  const range = (u, min, max, key) => fittedRange(u, key, !!plot.unit2, set.framing());
  /** @type {uPlot.Scales} */
  const scales = {
    // While zoomed, new data keeps the window; otherwise the axis spans the data.
    x: { time: false, auto: () => set.window === null },
    y: plot.log ? { distr: 3, log: 10, range: logRange } : { range },
  };
  if (plot.unit2) scales.y2 = { range };
  return {
    title: set.title(plot),
    width,
    height: set.height,
    scales,
    series: seriesOf(plot, set.scale),
    axes: axesOf(plot, set.scale),
    cursor: {
      // The charts share the cursor only: a drag zooms the chart it is on, and its set passes
      // the window on (Plots.zoomed), so that no other chart zooms by its own, older scale.
      sync: { key: SYNC_KEY, setSeries: false, filters: { pub: (type) => type === 'mousemove', sub: () => true } },
      drag: { x: true, y: false },
      bind: {
        dblclick: () => () => {
          set.onFull();
          return null;
        },
      },
    },
    hooks: {
      setScale: [(u, key) => key === 'x' && set.zoomed(u)],
      ready: [(u) => pickOnClick(set, u)],
      draw: [(u) => drawMarker(set, u)],
    },
  };
}
