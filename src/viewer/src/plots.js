// 2-D canvases: the timeline strip (colliding / within-tolerance steps marked) and the
// clearance-versus-time plot (per link, from the report's per-step link clearances).

export const LINK_COLORS = ['#555555', '#1f77b4', '#2ca02c', '#9467bd', '#d62728', '#8c564b',
  '#e377c2', '#17becf', '#bcbd22', '#ff7f0e'];

function sizeCanvas(canvas) {
  const ratio = window.devicePixelRatio || 1;
  const width = canvas.clientWidth;
  const height = canvas.clientHeight;
  if (canvas.width !== Math.round(width * ratio)) canvas.width = Math.round(width * ratio);
  if (canvas.height !== Math.round(height * ratio)) canvas.height = Math.round(height * ratio);
  const g = canvas.getContext('2d');
  g.setTransform(ratio, 0, 0, ratio, 0, 0);
  return { g, width, height };
}

/// Step class: 'collision' (unexpanded robot intersects), 'tolerance' (only the expanded robot
/// interferes), or 'clear'.
export function stepClass(step) {
  if (step.unexpanded_collides) return 'collision';
  if (step.expanded_interferes || step.interference_points.length > 0) return 'tolerance';
  return 'clear';
}

export function drawTimeline(canvas, steps, current) {
  const { g, width, height } = sizeCanvas(canvas);
  g.clearRect(0, 0, width, height);
  g.fillStyle = '#e4e7eb';
  g.fillRect(0, 0, width, height);
  const n = steps.length;
  if (n === 0) return;
  const x = (i) => (n === 1 ? width / 2 : (i / (n - 1)) * (width - 2) + 1);
  for (let i = 0; i < n; ++i) {
    const kind = stepClass(steps[i]);
    if (kind === 'clear') continue;
    g.fillStyle = kind === 'collision' ? '#d01010' : '#f0a020';
    g.fillRect(x(i) - 1.5, 0, 3, height);
  }
  g.fillStyle = '#1d3557';
  g.fillRect(x(current) - 1, 0, 2, height);
}

/// `links`: the link numbers to draw (those with hulls); `labelOf(link)`: the legend's text.
export function drawClearancePlot(canvas, steps, current, links, labelOf) {
  const { g, width, height } = sizeCanvas(canvas);
  g.clearRect(0, 0, width, height);
  g.fillStyle = '#ffffff';
  g.fillRect(0, 0, width, height);
  const left = 38, right = 8, top = 8, bottom = 18;
  const plotW = width - left - right, plotH = height - top - bottom;
  const n = steps.length;
  if (n === 0) return;
  const t0 = steps[0].path_time, t1 = Math.max(steps[n - 1].path_time, t0 + 1e-9);
  let maxClearance = 0;
  for (const step of steps) {
    for (const link of step.links) {
      if (link.clearance != null && links.includes(link.link)) maxClearance = Math.max(maxClearance, link.clearance);
    }
  }
  maxClearance = maxClearance > 0 ? maxClearance * 1.05 : 1;
  const px = (t) => left + ((t - t0) / (t1 - t0)) * plotW;
  const py = (c) => top + plotH - (c / maxClearance) * plotH;
  g.strokeStyle = '#999';
  g.lineWidth = 1;
  g.strokeRect(left, top, plotW, plotH);
  g.fillStyle = '#333';
  g.font = '10px sans-serif';
  g.textAlign = 'right';
  for (const fraction of [0, 0.5, 1]) {
    const c = maxClearance * fraction;
    g.fillText(c.toFixed(1), left - 3, py(c) + 3);
  }
  g.textAlign = 'center';
  g.fillText(`${t0.toFixed(1)} s`, left, height - 4);
  g.fillText(`${t1.toFixed(1)} s`, left + plotW, height - 4);
  g.fillText('clearance vs time', left + plotW / 2, height - 4);
  for (const link of links) {
    g.strokeStyle = LINK_COLORS[link % LINK_COLORS.length];
    g.lineWidth = 1.5;
    g.beginPath();
    let pen = false;
    for (const step of steps) {
      const record = step.links[link];
      if (!record || record.clearance == null) { pen = false; continue; }
      const X = px(step.path_time), Y = py(record.clearance);
      if (pen) g.lineTo(X, Y); else g.moveTo(X, Y);
      pen = true;
    }
    g.stroke();
  }
  // Legend: the links' names (or numbers) in rows from the top left of the plot.
  g.textAlign = 'left';
  let legendX = left + 4, legendY = top + 11;
  for (const link of links) {
    const text = labelOf(link);
    const width = g.measureText(text).width;
    if (legendX + width > left + plotW - 4 && legendX > left + 4) { legendX = left + 4; legendY += 12; }
    g.fillStyle = 'rgba(255,255,255,0.85)';  // legible over the curves
    g.fillRect(legendX - 2, legendY - 9, width + 4, 12);
    g.fillStyle = LINK_COLORS[link % LINK_COLORS.length];
    g.fillText(text, legendX, legendY);
    legendX += width + 8;
  }
  const X = px(steps[current].path_time);
  g.strokeStyle = '#1d3557';
  g.setLineDash([3, 3]);
  g.beginPath();
  g.moveTo(X, top);
  g.lineTo(X, top + plotH);
  g.stroke();
  g.setLineDash([]);
}
