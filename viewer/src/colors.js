// Colours: one per group, from a palette of well-separated hues, and the quality ramp.

// Saturated hues far apart, so that neighbouring groups never look alike; past the end the
// palette repeats, lighter.
const kPalette = [
  [0.91, 0.47, 0.18], // orange
  [0.24, 0.71, 0.29], // green
  [0.83, 0.2, 0.79], // magenta
  [0.9, 0.78, 0.1], // yellow
  [0.56, 0.31, 0.88], // violet
  [0.13, 0.7, 0.7], // teal
  [0.84, 0.2, 0.29], // red
  [0.31, 0.5, 0.88], // blue
];

export function groupColor(index) {
  const base = kPalette[index % kPalette.length];
  const lighten = Math.min(0.6, 0.25 * Math.floor(index / kPalette.length));
  return base.map((c) => c + (1 - c) * lighten);
}

export function hexOf(rgb) {
  return '#' + rgb.map((c) => Math.round(c * 255).toString(16).padStart(2, '0')).join('');
}

function hsvToRgb(h, s, v) {
  const f = (n) => {
    const k = (n + h / 60) % 6;
    return v - v * s * Math.max(0, Math.min(k, 4 - k, 1));
  };
  return [f(5), f(3), f(1)];
}

// Quality 0 (flat or inverted) is red, 1 (ideal) blue, through yellow, green and cyan.
export function qualityColor(q) {
  const t = Math.max(0, Math.min(1, Number.isFinite(q) ? q : 0));
  return hsvToRgb(240 * t, 0.85, 0.95);
}

export const kEdgeColor = [0.12, 0.12, 0.14];
export const kLineColorInQuality = [0.25, 0.25, 0.28];
