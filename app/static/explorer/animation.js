// The paper's constructions, frame by frame: (D4b) Wunderlich's stick sliding along the axis, its
// free end tracing the tractrix and the rotation centres p_i appearing; (D4a) Sauer's steps;
// (D1) the sticks of the hanging chain one by one, with the equilibrium read off each hinge;
// Theorem 11 the (D2b) polygons as j doubles, closing in on the catenary. Every frame is drawn
// from the API's numbers and described in words with its values (the text under the picture).

// @ts-check
// Type-checked by `make contract` against the types generated from the OpenAPI document.

import { plotSVG, widthFor, PALETTE } from './plot.js';

/** @typedef {import('../../../tools/contract/api-types').components['schemas']} Schemas */
/** A curve response, float64 or mp. @typedef {Schemas['CurveResponse'] | Schemas['CurveResponseMP']} Curve */
/** @typedef {import('./plot.js').Point} Point */
/** @typedef {import('./plot.js').Series} Series */
/** @typedef {{series: Series[], text: string}} Frame */
/** @typedef {{title: string, frames: Frame[], bounds: Point[]}} Movie */
/** The explorer's JSON fetcher. @typedef {(url: string) => Promise<Curve>} GetJSON */
/**
 * The page elements the animation drives.
 * @typedef {{section: HTMLElement, title: HTMLElement, plot: HTMLElement, text: HTMLElement,
 *   play: HTMLButtonElement, back: HTMLButtonElement, forward: HTMLButtonElement,
 *   slider: HTMLInputElement}} Elements
 */

/** @param {Curve['vertices']} points @returns {Point[]} */
const num = (points) => points.map(([x, y]) => /** @type {Point} */ ([Number(x), Number(y)]));
const fmt = (/** @type {number | string} */ v) => (Math.abs(Number(v)) < 1e-12 ? '0' : String(Number(Number(v).toPrecision(5))).replace('-', '−'));
const pt = (/** @type {Point} */ [x, y]) => `(${fmt(x)}, ${fmt(y)})`;
const dist = (/** @type {Point} */ a, /** @type {Point} */ b) => Math.hypot(a[0] - b[0], a[1] - b[1]);
/** @param {Point} c @param {Point} a @param {Point} b */
const angle = (c, a, b) => {
  const u = [a[0] - c[0], a[1] - c[1]], v = [b[0] - c[0], b[1] - c[1]];
  return Math.abs(Math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]));
};

/** @param {Curve} curve @param {string} kind @returns {Movie} */
function kinematic(curve, kind) {
  const p = num(curve.vertices);
  const d = num(curve.companions.tractrix.vertices);
  const x = num(curve.companions.axis_points.vertices);
  const idx = curve.indices;
  // (D4b): p_i turns stick i − 1 into stick i (erratum E1); (D4a): p_i turns stick i into i + 1
  const centre = (/** @type {number} */ k) => (kind === 'd4b' ? k : k - 1);
  const frames = idx.map((i, k) => {
    const c = centre(k);
    /** @type {Series[]} */
    const series = [
      { name: 'tractrix', label: 'tractrix d so far', points: d.slice(0, k + 1), color: PALETTE[1], width: 1.5 },
      { name: 'centres', label: 'rotation centres p so far', points: p.slice(0, Math.max(c + 1, 0)), color: PALETTE[0], width: 2 },
      { name: 'stick', label: 'stick i', points: [x[k], d[k]], color: '#000000', width: 3, markers: true },
    ];
    if (k > 0) {
      series.splice(2, 0, { name: 'previous-stick', label: 'stick i − 1', points: [x[k - 1], d[k - 1]], color: '#888888', width: 2, dashed: true, markers: false });
      if (c >= 0 && c < p.length) {
        series.push({ name: 'radii', label: 'from the centre to both sticks', points: [d[k - 1], p[c], d[k]], color: PALETTE[2], width: 1, dashed: true, markers: false });
      }
    }
    let text = `i = ${fmt(i)}: stick i from x_i = ${pt(x[k])} to d_i = ${pt(d[k])}, length ${fmt(dist(x[k], d[k]))}.`;
    if (k > 0 && c >= 0 && c < p.length) {
      const turn = angle(p[c], x[k - 1], x[k]);
      text += ` It is stick i − 1 turned about p_${fmt(idx[c])} = ${pt(p[c])} by ${fmt(turn)} rad;`;
      text += kind === 'd4b'
        ? ` 2 arctan(d/p_i^y) = ${fmt(2 * Math.atan(Number(curve.parameters.d) / p[c][1]))}.`
        : ` the tractrix edge |d_i − d_(i−1)| = ${fmt(dist(d[k], d[k - 1]))} (s = ${fmt(Number(curve.parameters.s))}).`;
    }
    return { series, text };
  });
  const title = kind === 'd4b'
    ? "(D4b) Wunderlich's stick slides along the x-axis: its free end d_i traces the tractrix, each step a rotation about p_i."
    : "(D4a) Sauer's construction: each stick is the previous one turned about p_i, its end moving by s along it.";
  return { title, frames, bounds: [...p, ...d, ...x] };
}

/** @param {Curve} curve @returns {Movie} */
function hangingSticks(curve) {
  const p = num(curve.vertices);
  const c = Number(curve.constants.equilibrium ?? curve.constants.d1);
  const slope = (/** @type {number} */ k) => (p[k + 1][1] - p[k][1]) / (p[k + 1][0] - p[k][0]);
  /** @type {Frame[]} */
  const frames = [];
  for (let k = 0; k + 1 < p.length; k++) {
    /** @type {Series[]} */
    const series = [
      { name: 'chain', label: 'the whole chain', points: p, color: '#bbbbbb', width: 1, dashed: true, markers: false },
      { name: 'sticks', label: 'sticks hung so far', points: p.slice(0, k + 2), color: PALETTE[0], width: 3 },
      { name: 'hinge', label: 'the new hinge', points: [p[k + 1]], color: PALETTE[1], width: 2 },
    ];
    const l = dist(p[k], p[k + 1]);
    let text = `Stick ${k + 1} from p_${fmt(curve.indices[k])} = ${pt(p[k])} to p_${fmt(curve.indices[k + 1])} = ${pt(p[k + 1])}: length l = ${fmt(l)}, slope k = ${fmt(slope(k))}.`;
    if (k > 0) {
      const change = slope(k) - slope(k - 1);
      const weight = c * (dist(p[k - 1], p[k]) + l);
      text += ` At the hinge p_${fmt(curve.indices[k])}: slope change ${fmt(change)}, c(l_prev + l) = ${fmt(weight)} with c = ${fmt(c)} (equilibrium).`;
    }
    frames.push({ series, text });
  }
  return { title: '(D1) as a hanging chain: homogeneous sticks joined by hinges; at each hinge the slope changes by c times the two lengths.', frames, bounds: p };
}

/** The (D2b) polygons of each sequence, by j. @type {Map<string, [number, Point[]][]>} */
const LEVELS = new Map();

/** @param {Curve} curve @param {GetJSON} getJSON @returns {Promise<Movie | null>} */
async function convergence(curve, getJSON) {
  const sequence = curve.parameters.sequence;
  if (sequence !== 'example-12' && sequence !== 'remark-13') return null;
  const levels = [1, 2, 4, 8, 16, 32];
  // the levels depend on the sequence only: fetched once per sequence, not on every change
  if (!LEVELS.has(sequence)) {
    /** @type {[number, Point[]][]} */
    const polygons = [];
    for (const j of levels) {
      // only the polygon is drawn: no checks, no companions computed (issue 12's selection)
      const body = await getJSON(`/discretizations/d2b?sequence=${sequence}&j=${j}&checks=none&companions=none`);
      polygons.push([j, num(body.vertices)]);
    }
    LEVELS.set(sequence, polygons);
  }
  const polygons = LEVELS.get(sequence) ?? [];
  const all = polygons.flatMap(([, points]) => points);
  const xs = all.map(([x]) => x);
  const [x0, x1] = [Math.min(...xs), Math.max(...xs)];
  const catenary = Array.from({ length: 121 }, (_, k) => { const x = x0 + (k / 120) * (x1 - x0); return /** @type {Point} */ ([x, Math.cosh(x)]); });
  const frames = polygons.map(([j, points], k) => {
    const gap = Math.max(...points.map(([x, y]) => Math.abs(y - Math.cosh(x))));
    /** @type {Series[]} */
    const series = [
      { name: 'catenary', label: 'the catenary C = (x, cosh x)', points: catenary, color: '#555555', dashed: true, markers: false, width: 1.2 },
      ...(k > 0 ? [{ name: 'previous', label: `p^j for j = ${polygons[k - 1][0]}`, points: polygons[k - 1][1], color: '#aaaaaa', width: 1 }] : []),
      { name: 'polygon', label: `p^j for j = ${j}`, points, color: PALETTE[0], width: 2 },
    ];
    return { series, text: `j = ${j} (${sequence}): ${points.length} vertices; the largest vertical distance to the catenary, max |p_i^y − cosh p_i^x| = ${fmt(gap)}.` };
  });
  return { title: 'Theorem 11: the (D2b) meridians p^j for j = 1, 2, 4, …, 32 close in on the catenary.', frames, bounds: [...all, ...catenary] };
}

// frames for the discretization shown, or null when it has no animation
/** @param {Curve} curve @param {GetJSON} getJSON @returns {Promise<Movie | null>} */
async function build(curve, getJSON) {
  if (curve.id === 'd4b' || curve.id === 'd4a') return kinematic(curve, curve.id);
  if (curve.id === 'd1') return hangingSticks(curve);
  if (curve.id === 'd2b') return convergence(curve, getJSON);
  return null;
}

export class Animation {
  /** @param {Elements} elements */
  constructor(elements) {
    this.el = elements;
    /** @type {Movie | null} */
    this.movie = null;
    this.frame = 0;
    /** @type {ReturnType<typeof setInterval> | undefined} */
    this.timer = undefined;
    this.el.play.addEventListener('click', () => (this.timer ? this.pause() : this.play()));
    this.el.back.addEventListener('click', () => { this.pause(); this.show(this.frame - 1); });
    this.el.forward.addEventListener('click', () => { this.pause(); this.show(this.frame + 1); });
    this.el.slider.addEventListener('input', () => { this.pause(); this.show(Number(this.el.slider.value)); });
  }

  /** @param {Curve | null} curve @param {GetJSON} getJSON */
  async update(curve, getJSON) {
    this.pause();
    let movie = null;
    try { movie = curve ? await build(curve, getJSON) : null; } catch (error) {
      this.el.title.textContent = `No animation: ${error instanceof Error ? error.message : String(error)}`;
    }
    this.movie = movie;
    this.el.section.hidden = !movie;
    if (!movie) return;
    this.el.title.textContent = movie.title;
    this.el.slider.max = String(movie.frames.length - 1);
    this.show(Math.min(this.frame, movie.frames.length - 1));
  }

  /** @param {number} frame */
  show(frame) {
    if (!this.movie) return;
    const n = this.movie.frames.length;
    this.frame = Math.max(0, Math.min(n - 1, frame));
    const { series, text } = this.movie.frames[this.frame];
    const drawn = series.filter((s) => s.points.length);
    const width = widthFor(this.el.plot);
    this.el.plot.replaceChildren(plotSVG(drawn, {
      title: `${this.el.title.textContent} Frame ${this.frame + 1} of ${n}.`, bounds: this.movie.bounds,
      id: 'animation-plot', width, height: Math.round(width * 0.58),
    }));
    this.el.slider.value = String(this.frame);
    this.el.slider.setAttribute('aria-valuetext', `Frame ${this.frame + 1} of ${n}`);
    this.el.text.textContent = `Frame ${this.frame + 1} of ${n}. ${text}`;
    this.el.section.dataset.frame = String(this.frame);
    this.el.back.disabled = this.frame === 0;
    this.el.forward.disabled = this.frame === n - 1;
  }

  play() {
    if (!this.movie) return;
    if (this.frame >= this.movie.frames.length - 1) this.show(0);
    this.el.play.textContent = 'Pause';
    this.el.play.setAttribute('aria-pressed', 'true');
    this.el.text.setAttribute('aria-live', 'off'); // no stream of announcements while it runs
    this.el.section.dataset.playing = 'true';
    const movie = this.movie;
    this.timer = setInterval(() => {
      if (this.frame >= movie.frames.length - 1) { this.pause(); return; }
      this.show(this.frame + 1);
    }, 700);
  }

  pause() {
    clearInterval(this.timer);
    this.timer = undefined;
    this.el.play.textContent = 'Play';
    this.el.play.setAttribute('aria-pressed', 'false');
    this.el.text.setAttribute('aria-live', 'polite');
    this.el.section.dataset.playing = 'false';
  }
}
