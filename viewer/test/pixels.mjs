// Reading screenshots for the viewer's tests: PNG decoding (8-bit RGB or RGBA, as Chromium
// writes them) and colour statistics that do not depend on how brightly a face is lit.
import { inflateSync } from 'node:zlib';

function paeth(a, b, c) {
  const p = a + b - c;
  const pa = Math.abs(p - a);
  const pb = Math.abs(p - b);
  const pc = Math.abs(p - c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

// { width, height, rgba: Uint8Array } from a PNG file's bytes.
export function decodePng(buffer) {
  if (buffer.readUInt32BE(0) !== 0x89504e47) throw new Error('not a PNG');
  let offset = 8;
  let width = 0;
  let height = 0;
  let channels = 0;
  const data = [];
  while (offset < buffer.length) {
    const length = buffer.readUInt32BE(offset);
    const type = buffer.toString('latin1', offset + 4, offset + 8);
    const body = buffer.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0);
      height = body.readUInt32BE(4);
      const [depth, colorType, , , interlace] = body.subarray(8, 13);
      if (depth !== 8 || interlace !== 0 || (colorType !== 2 && colorType !== 6))
        throw new Error(`PNG layout not handled: depth ${depth}, colour type ${colorType}`);
      channels = colorType === 6 ? 4 : 3;
    } else if (type === 'IDAT') {
      data.push(body);
    }
    offset += 12 + length;
  }
  const raw = inflateSync(Buffer.concat(data));
  const stride = width * channels;
  const pixels = new Uint8Array(stride * height);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; ++x) {
      const a = x >= channels ? pixels[y * stride + x - channels] : 0;
      const b = y > 0 ? pixels[(y - 1) * stride + x] : 0;
      const c = x >= channels && y > 0 ? pixels[(y - 1) * stride + x - channels] : 0;
      const predictor = [0, a, b, (a + b) >> 1, paeth(a, b, c)][filter];
      pixels[y * stride + x] = (line[x] + predictor) & 255;
    }
  }
  const rgba = new Uint8Array(4 * width * height);
  for (let i = 0; i < width * height; ++i) {
    rgba.set(pixels.subarray(i * channels, i * channels + 3), 4 * i);
    rgba[4 * i + 3] = channels === 4 ? pixels[i * channels + 3] : 255;
  }
  return { width, height, rgba };
}

// Hue in degrees, saturation and value in [0, 1].
export function hsv(r, g, b) {
  const max = Math.max(r, g, b);
  const min = Math.min(r, g, b);
  const d = max - min;
  let h = 0;
  if (d > 0) {
    if (max === r) h = (60 * ((g - b) / d) + 360) % 360;
    else if (max === g) h = 60 * ((b - r) / d + 2);
    else h = 60 * ((r - g) / d + 4);
  }
  return { h, s: max === 0 ? 0 : d / max, v: max / 255 };
}

export function parseHex(hex) {
  return [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
}

function hueDistance(a, b) {
  const d = Math.abs(a - b) % 360;
  return Math.min(d, 360 - d);
}

// The share of the picture's pixels whose colour is `rgb` lit more or less: the same hue and
// about the same saturation (lighting scales a colour, keeping both).
export function colourShare(image, rgb, tolerance = 8) {
  const target = hsv(...rgb);
  let count = 0;
  const n = image.width * image.height;
  for (let i = 0; i < n; ++i) {
    const c = hsv(image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]);
    if (c.v > 0.2 && Math.abs(c.s - target.s) < 0.12 && hueDistance(c.h, target.h) < tolerance)
      count += 1;
  }
  return count / n;
}

// The share of saturated pixels whose hue lies in [from, to] degrees.
export function hueRangeShare(image, from, to, minSaturation = 0.6) {
  let count = 0;
  const n = image.width * image.height;
  for (let i = 0; i < n; ++i) {
    const c = hsv(image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]);
    if (c.v > 0.2 && c.s >= minSaturation && c.h >= from && c.h <= to) count += 1;
  }
  return count / n;
}

// The share of pixels that differ (by more than a little) between two pictures of one size.
export function changedShare(a, b) {
  if (a.width !== b.width || a.height !== b.height) return 1;
  let count = 0;
  for (let i = 0; i < a.width * a.height; ++i) {
    let d = 0;
    for (let k = 0; k < 3; ++k) d = Math.max(d, Math.abs(a.rgba[4 * i + k] - b.rgba[4 * i + k]));
    if (d > 24) count += 1;
  }
  return count / (a.width * a.height);
}

// How many distinct colours (quantised to 4 bits a channel) the picture holds.
export function distinctColours(image) {
  const seen = new Set();
  for (let i = 0; i < image.width * image.height; ++i)
    seen.add(((image.rgba[4 * i] >> 4) << 8) | ((image.rgba[4 * i + 1] >> 4) << 4) |
      (image.rgba[4 * i + 2] >> 4));
  return seen.size;
}
