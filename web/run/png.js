// The PNG export's image: the plots' canvases, each under its title and colour key, below the
// scenario and the run's figures.

/**
 * One PNG of `figures` (from Plots.figures()) under a header of text lines (the scenario and the
 * run's figures): each plot with its title and a colour key of its series.
 */
export async function png(figures, header) {
  const scale = devicePixelRatio || 1;
  const line = 22 * scale;
  const font = `${15 * scale}px system-ui`;
  const width = Math.max(...figures.map((f) => f.canvas.width));
  const out = document.createElement('canvas');
  const ctx = out.getContext('2d');
  // Lay out the colour keys first to know each one's height.
  ctx.font = font;
  const keyRows = figures.map((f) => {
    const rows = [[]];
    let x = 8 * scale;
    for (const k of f.key) {
      const w = 40 * scale + ctx.measureText(k.label).width + 16 * scale;
      if (x + w > width && rows.at(-1).length) {
        rows.push([]);
        x = 8 * scale;
      }
      rows.at(-1).push({ ...k, x });
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
