// A small SVG plotter for the explorer: equal scales, axes with ticks, one <g> per series.
// It mirrors the server's writer (app/rendering/svg.py) so that both pictures read alike.

// @ts-check
// Type-checked by `make contract` (tsc --strict --checkJs, tools/contract/tsconfig.explorer.json).

/** A point as the plot reads it. @typedef {[number, number]} Point */
/**
 * One drawn polyline.
 * @typedef {{name: string, label: string, points: Point[], color: string, width?: number,
 *   dashed?: boolean, markers?: boolean}} Series
 */

const NS = 'http://www.w3.org/2000/svg';
export const PALETTE = ['#0072B2', '#D55E00', '#009E73', '#CC79A7', '#E69F00', '#56B4E9', '#000000'];
const MAX_MARKERS = 400;

/**
 * @param {string} name
 * @param {Record<string, string | number>} [attributes]
 * @param {string | null} [text]
 */
function el(name, attributes = {}, text = null) {
  const node = document.createElementNS(NS, name);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, String(value));
  if (text !== null) node.textContent = text;
  return node;
}

/** @param {number} span @param {number} target */
function niceStep(span, target) {
  const raw = span / Math.max(target, 1);
  const magnitude = 10 ** Math.floor(Math.log10(raw));
  for (const factor of [1, 2, 5, 10]) if (factor * magnitude >= raw) return factor * magnitude;
  return 10 * magnitude;
}

/** @param {number} value @param {number} step */
function tickLabel(value, step) {
  const decimals = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
  if (Math.abs(value) < step * 1e-6) value = 0;
  let text = value.toFixed(Math.min(decimals, 20));
  if (Math.abs(value) >= 1e6 || (value !== 0 && Math.abs(value) < 1e-4)) text = value.toPrecision(3);
  return text.replace('-', '\u2212');
}

/** @param {number[]} values @returns {[number, number]} */
function range(values) {
  let low = Infinity;
  let high = -Infinity;
  for (const v of values) { if (v < low) low = v; if (v > high) high = v; }
  if (!Number.isFinite(low)) return [-1, 1];
  if (high - low < 1e-12 * Math.max(1, Math.abs(low), Math.abs(high))) {
    const pad = Math.max(0.5, Math.abs(low) * 0.1);
    return [low - pad, high + pad];
  }
  return [low, high];
}

// The picture's width in its own units for a container: on a phone the plot is drawn narrower
// (not scaled down), so that its labels keep their size.
/** @param {HTMLElement | null | undefined} container */
export function widthFor(container) {
  const available = container?.clientWidth || 800;
  return Math.round(Math.max(340, Math.min(800, available)));
}

// series: [{name, label, points: [[x, y], ...], color, dashed, width, markers}]
// bounds: [[x, y], ...] points the view must include (a fixed frame for an animation);
// id: distinguishes the clip path of several plots on one page.
/**
 * @param {Series[]} series
 * @param {{width?: number, height?: number, title?: string, bounds?: Point[], id?: string}} [options]
 */
export function plotSVG(series, { width = 800, height = 520, title = '', bounds = [], id = 'explorer-plot' } = {}) {
  const left = 60, right = width - 12, top = 12, bottom = height - 44;
  /** @type {number[]} */
  const xs = [];
  /** @type {number[]} */
  const ys = [];
  for (const s of series) for (const [x, y] of s.points) { xs.push(x); ys.push(y); }
  for (const [x, y] of bounds) { xs.push(x); ys.push(y); }
  let [x0, x1] = range(xs);
  let [y0, y1] = range(ys);
  const padx = 0.04 * (x1 - x0), pady = 0.06 * (y1 - y0);
  x0 -= padx; x1 += padx; y0 -= pady; y1 += pady;
  const w = right - left, h = bottom - top;
  const b = Math.min(w / (x1 - x0), h / (y1 - y0));
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  x0 = cx - w / (2 * b); x1 = cx + w / (2 * b); y0 = cy - h / (2 * b); y1 = cy + h / (2 * b);
  const X = (/** @type {number} */ x) => left + b * (x - x0);
  const Y = (/** @type {number} */ y) => top + b * (y1 - y);

  const svg = el('svg', {
    viewBox: `0 0 ${width} ${height}`, role: 'img', 'aria-label': title,
    'font-family': 'DejaVu Sans, Helvetica, Arial, sans-serif', 'font-size': 12,
  });
  svg.append(el('title', {}, title));
  svg.append(el('rect', { x: 0, y: 0, width, height, fill: '#ffffff' }));
  const defs = el('defs');
  const clip = el('clipPath', { id: `${id}-area` });
  clip.append(el('rect', { x: left, y: top, width: w, height: h }));
  defs.append(clip);
  svg.append(defs);

  const axes = el('g', { class: 'axes', stroke: '#333333', fill: '#222222' });
  axes.append(el('rect', { x: left, y: top, width: w, height: h, fill: 'none', stroke: '#999999' }));
  const xTarget = Math.max(3, Math.floor(w / 90)), yTarget = Math.max(3, Math.floor(h / 60));
  const xStep = niceStep(x1 - x0, xTarget), yStep = niceStep(y1 - y0, yTarget);
  for (let k = Math.ceil(x0 / xStep - 1e-9); k <= Math.floor(x1 / xStep + 1e-9); k++) {
    const px = X(k * xStep);
    const g = el('g', { class: 'tick x' });
    g.append(el('line', { x1: px, y1: top, x2: px, y2: bottom, stroke: '#eeeeee' }));
    g.append(el('text', { x: px, y: bottom + 18, 'text-anchor': 'middle', stroke: 'none' }, tickLabel(k * xStep, xStep)));
    axes.append(g);
  }
  for (let k = Math.ceil(y0 / yStep - 1e-9); k <= Math.floor(y1 / yStep + 1e-9); k++) {
    const py = Y(k * yStep);
    const g = el('g', { class: 'tick y' });
    g.append(el('line', { x1: left, y1: py, x2: right, y2: py, stroke: '#eeeeee' }));
    g.append(el('text', { x: left - 8, y: py, dy: '0.35em', 'text-anchor': 'end', stroke: 'none' }, tickLabel(k * yStep, yStep)));
    axes.append(g);
  }
  if (y0 <= 0 && 0 <= y1) axes.append(el('line', { x1: left, y1: Y(0), x2: right, y2: Y(0), stroke: '#777777' }));
  if (x0 <= 0 && 0 <= x1) axes.append(el('line', { x1: X(0), y1: top, x2: X(0), y2: bottom, stroke: '#777777' }));
  axes.append(el('text', { x: (left + right) / 2, y: bottom + 36, 'text-anchor': 'middle', stroke: 'none' }, 'x'));
  axes.append(el('text', { x: 14, y: (top + bottom) / 2, 'text-anchor': 'middle', stroke: 'none' }, 'y'));
  svg.append(axes);

  const data = el('g', { class: 'data', 'clip-path': `url(#${id}-area)` });
  for (const s of series) {
    const g = el('g', { class: 'series', 'data-name': s.name });
    g.append(el('title', {}, s.label));
    const pts = s.points.map(([x, y]) => `${X(x).toFixed(2)},${Y(y).toFixed(2)}`).join(' ');
    const line = el('polyline', {
      points: pts, fill: 'none', stroke: s.color, 'stroke-width': s.width || 1.5, 'stroke-linejoin': 'round',
    });
    if (s.dashed) line.setAttribute('stroke-dasharray', '6 4');
    g.append(line);
    if (s.markers !== false && s.points.length <= MAX_MARKERS) {
      for (const [x, y] of s.points) g.append(el('circle', { cx: X(x).toFixed(2), cy: Y(y).toFixed(2), r: 2.2, fill: s.color }));
    }
    data.append(g);
  }
  svg.append(data);
  return svg;
}
