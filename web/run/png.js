// The PNG export's image: the plots' canvases, each under its title and colour key, below the
// scenario and the run's figures.

/**
 * A series in a plot's colour key: its label, and its line's colour and dashes (px at scale 1).
 * @typedef {{label: string, stroke: string | CanvasGradient | CanvasPattern, dash?: number[]}} KeyEntry
 */

/**
 * A plot as Plots.figures() gives it: its chart's canvas, its title and its colour key.
 * @typedef {{canvas: HTMLCanvasElement, title: string, key: KeyEntry[]}} PlotImage
 */

/**
 * A row of a colour key in the image, each series with its left edge.
 * @typedef {(KeyEntry & {x: number})[]} KeyRow
 */

/**
 * One PNG of `figures` (from Plots.figures()) under a header of text lines (the scenario and the
 * run's figures): each plot with its title and a colour key of its series.
 * @param {PlotImage[]} figures
 * @param {string[]} header
 * @returns {Promise<Blob | null>}
 */
export async function png(figures, header) {
  const scale = devicePixelRatio || 1;
  const line = 22 * scale;
  const font = `${15 * scale}px system-ui`;
  const width = Math.max(...figures.map((f) => f.canvas.width));
  const out = document.createElement('canvas');
  // A new canvas has no context yet, so it gives its 2D one.
  const ctx = /** @type {CanvasRenderingContext2D} */ (out.getContext('2d'));
  // Lay out the colour keys first to know each one's height.
  ctx.font = font;
  const keyRows = figures.map((f) => {
    /** @type {KeyRow[]} never empty: it starts with one row and only grows */
    const rows = [[]];
    let x = 8 * scale;
    for (const k of f.key) {
      const w = 40 * scale + ctx.measureText(k.label).width + 16 * scale;
      if (x + w > width && /** @type {KeyRow} */ (rows.at(-1)).length) {
        rows.push([]);
        x = 8 * scale;
      }
      /** @type {KeyRow} */ (rows.at(-1)).push({ ...k, x });
      x += w;
    }
    return rows;
  });
  const headerH = header.length * line + 8 * scale;
  out.width = width;
  out.height =
    headerH + figures.reduce((h, f, i) => h + line * (1 + keyRows[i].length) + f.canvas.height + 8 * scale, 0);
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, out.width, out.height);
  ctx.fillStyle = '#000';
  ctx.font = font;
  header.forEach((text, i) => ctx.fillText(text, 8 * scale, (i + 1) * line - 6 * scale));
  let y = headerH;
  figures.forEach((f, i) => {
    ctx.fillStyle = '#000';
    ctx.font = `bold ${16 * scale}px system-ui`;
    ctx.fillText(f.title, 8 * scale, y + line - 6 * scale);
    y += line;
    ctx.font = font;
    for (const row of keyRows[i]) {
      for (const k of row) {
        ctx.strokeStyle = k.stroke;
        ctx.lineWidth = 2 * scale;
        ctx.setLineDash((k.dash ?? []).map((d) => d * scale));
        ctx.beginPath();
        ctx.moveTo(k.x, y + line / 2);
        ctx.lineTo(k.x + 32 * scale, y + line / 2);
        ctx.stroke();
        ctx.setLineDash([]);
        ctx.fillStyle = '#000';
        ctx.fillText(k.label, k.x + 38 * scale, y + line - 6 * scale);
      }
      y += line;
    }
    ctx.drawImage(f.canvas, 0, y);
    y += f.canvas.height + 8 * scale;
  });
  return new Promise((resolve) => out.toBlob(resolve, 'image/png'));
}
