// Inspecting a time on a set of plots: a click or the arrow keys pick it, and a dashed line
// marks it on every chart.

/** @typedef {import('./plots.js').Plots} Plots */

/**
 * Arrow keys on a focused plot (`div`, chart `i` of `set`) move the inspect cursor one sample
 * (Ts), or 1 % of the visible window with Shift; Home and End go to the window's ends.
 * @param {Plots} set
 * @param {HTMLElement} div
 * @param {number} i
 */
export function inspectByKeys(set, div, i) {
  div.addEventListener('keydown', (e) => {
    const u = set.charts[i];
    if (!u || !set.full) return;
    // A drawn chart's time scale has its range.
    const { min, max } = /** @type {{min: number, max: number}} */ (u.scales.x);
    const step = e.shiftKey || !set.sampleTime() ? (max - min) / 100 : /** @type {number} */ (set.sampleTime());
    const from = set.marker ?? (min + max) / 2;
    /** @type {Partial<Record<string, number>>} the time each key goes to */
    const moves = { ArrowRight: from + step, ArrowLeft: from - step, Home: min, End: max };
    const to = moves[e.key];
    if (to === undefined) return;
    e.preventDefault();
    const t = Math.min(Math.max(to, set.full[0]), set.full[1]);
    set.mark(t);
    // The legend reads out the samples at the cursor, as it does for the mouse.
    u.setCursor({ left: u.valToPos(t, 'x'), top: u.bbox.height / devicePixelRatio / 2 });
    set.onPick(t);
  });
}

/**
 * A click (not a drag-to-zoom) on the plot area of chart `u` picks the time under the cursor.
 * @param {Plots} set
 * @param {uPlot} u
 */
export function pickOnClick(set, u) {
  /** @type {number | null} */
  let downX = null;
  u.over.addEventListener('mousedown', (e) => {
    downX = e.clientX;
  });
  u.over.addEventListener('click', (e) => {
    // uPlot always holds the cursor's position: negative while it is off the plot area.
    const left = /** @type {number} */ (u.cursor.left);
    if (downX !== null && Math.abs(e.clientX - downX) < 3 && left >= 0) set.onPick(u.posToVal(left, 'x'));
  });
}

/**
 * Draws the set's inspected time on chart `u`, if it is in the chart's window.
 * @param {Plots} set
 * @param {uPlot} u
 */
export function drawMarker(set, u) {
  if (set.marker === null) return;
  const x = Math.round(u.valToPos(set.marker, 'x', true));
  if (x < u.bbox.left || x > u.bbox.left + u.bbox.width) return;
  const { ctx } = u;
  ctx.save();
  ctx.strokeStyle = '#b00020';
  ctx.lineWidth = 1.5 * devicePixelRatio;
  ctx.setLineDash([4 * devicePixelRatio, 3 * devicePixelRatio]);
  ctx.beginPath();
  ctx.moveTo(x, u.bbox.top);
  ctx.lineTo(x, u.bbox.top + u.bbox.height);
  ctx.stroke();
  ctx.restore();
}
