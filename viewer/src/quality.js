// Quality over the elements of the mesh's highest dimension: statistics, a histogram drawn
// in the ramp's colours, and the worst elements.

import { qualityColor, hexOf } from './colors.js';

export const kBins = 20;

// The quality values of the top-dimension elements with their page element numbers.
function topElements(mesh, measure) {
  const values = [];
  for (const block of mesh.blocks) {
    if (block.dim !== mesh.topDim || !block.quality[measure]) continue;
    const q = block.quality[measure];
    for (let i = 0; i < block.count; ++i) values.push({ block, i, q: q[i] });
  }
  return values;
}

export function qualitySummary(mesh, measure) {
  const values = topElements(mesh, measure);
  const bins = new Array(kBins).fill(0);
  let min = Infinity;
  let sum = 0;
  for (const { q } of values) {
    const bin = Math.min(kBins - 1, Math.max(0, Math.floor(q * kBins)));
    bins[bin] += 1;
    min = Math.min(min, q);
    sum += q;
  }
  const worst = values
    .slice()
    .sort((a, b) => a.q - b.q || a.block.firstId + a.i - (b.block.firstId + b.i))
    .slice(0, 10);
  return { count: values.length, min, mean: values.length ? sum / values.length : 0, bins, worst };
}

// Bars of the bins on the canvas, each in the ramp's colour at its middle.
export function drawHistogram(canvas, bins) {
  const ratio = window.devicePixelRatio || 1;
  const width = canvas.clientWidth || 260;
  const height = canvas.clientHeight || 110;
  canvas.width = Math.round(width * ratio);
  canvas.height = Math.round(height * ratio);
  const g = canvas.getContext('2d');
  g.setTransform(ratio, 0, 0, ratio, 0, 0);
  g.clearRect(0, 0, width, height);
  const axis = 14;
  const highest = Math.max(1, ...bins);
  const barWidth = width / bins.length;
  bins.forEach((n, b) => {
    if (n === 0) return;
    const h = Math.max(1, ((height - axis - 2) * n) / highest);
    g.fillStyle = hexOf(qualityColor((b + 0.5) / bins.length));
    g.fillRect(b * barWidth + 1, height - axis - h, barWidth - 2, h);
  });
  g.fillStyle = '#555';
  g.font = '10px sans-serif';
  g.textBaseline = 'bottom';
  g.textAlign = 'left';
  g.fillText('0', 1, height);
  g.textAlign = 'center';
  g.fillText('0.5', width / 2, height);
  g.textAlign = 'right';
  g.fillText('1', width - 1, height);
}
