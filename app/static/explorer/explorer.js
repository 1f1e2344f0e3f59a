// The explorer: one page on top of the public API (GET /discretizations, /discretizations/{id},
// /figures, /smooth/{catenary,tractrix} and /surfaces); it never loads the OpenAPI document.
// Every value from the API is inserted as text (textContent), never as HTML.

// @ts-check
// Type-checked by `make contract` (tsc --strict --checkJs, tools/contract/tsconfig.explorer.json)
// against the types generated from the OpenAPI document.

import { plotSVG, widthFor, PALETTE } from './plot.js';
import { Animation } from './animation.js';

/** @typedef {import('../../../tools/contract/api-types').components['schemas']} Schemas */
/** A curve response, float64 or mp. @typedef {Schemas['CurveResponse'] | Schemas['CurveResponseMP']} Curve */
/** @typedef {Schemas['DiscretizationEntry']} Entry */
/** @typedef {Schemas['ParameterInfo']} Parameter */
/** @typedef {Schemas['SurfaceEntry']} Surface */
/** @typedef {Schemas['FigureEntry']} Figure */
/** @typedef {Schemas['StatementInfo']} Statement */
/** What the page shows of a problem (a fetched problem+json, or one made up for a bare status). */
/** @typedef {Pick<Schemas['Problem'], 'title' | 'detail' | 'errors'>} ProblemText */
/** @typedef {import('./plot.js').Point} Point */
/** @typedef {import('./plot.js').Series} Series */
/** A drawn overlay (another discretization, a smooth curve). @typedef {{label: string, points: Point[]}} Overlay */
/** KaTeX's global, as far as the explorer uses it. */
/** @typedef {{render: (tex: string, node: HTMLElement, options: Record<string, unknown>) => void}} Katex */
/** A form field that differs from its default: name, value as typed, kind. */
/** @typedef {[name: string, value: string, kind: string]} Changed */
/** A form field (the sliders excepted). @typedef {HTMLInputElement | HTMLSelectElement | HTMLTextAreaElement} Field */
/**
 * The part of a parameter's JSON Schema (`json_schema` in GET /discretizations) the form reads.
 * @typedef {{type?: string, enum?: (string | number)[], anyOf?: FieldSchema[], nullable?: boolean,
 *   minimum?: number, maximum?: number, exclusiveMinimum?: number, exclusiveMaximum?: number}} FieldSchema
 */

/** An element of the page, which is always there. @param {string} id @returns {HTMLElement} */
const $ = (id) => {
  const node = document.getElementById(id);
  if (!node) throw new Error(`#${id} is not on the page`);
  return node;
};
/** An element that may be absent (a field of another discretization). @param {string} id */
const maybe = (id) => document.getElementById(id);
/** @param {string} id */
const $input = (id) => /** @type {HTMLInputElement} */ ($(id));
/** @param {string} id */
const $select = (id) => /** @type {HTMLSelectElement} */ ($(id));
/** @param {string} id */
const $button = (id) => /** @type {HTMLButtonElement} */ ($(id));
/** @param {string} id */
const $tbody = (id) => /** @type {HTMLTableSectionElement} */ ($(id).querySelector('tbody'));
/** A property of what was thrown (an Error, a DOMException, anything). @param {unknown} error @param {string} key */
const thrown = (error, key) => (typeof error === 'object' && error !== null ? /** @type {Record<string, unknown>} */ (error)[key] : undefined);
/** @param {unknown} error */
const messageOf = (error) => String(thrown(error, 'message'));
/** @param {number | undefined} value @returns {value is number} */
const finite = (value) => Number.isFinite(value);

/**
 * @type {{catalog: Entry[], entry: Entry | null, curve: Curve | null,
 *   controller: AbortController | null, hidden: Set<string>, smooth: Record<string, Overlay>,
 *   surfaces: Surface[], figures: Figure[], katex: Katex | null, compare: Record<string, Overlay>,
 *   claimTex: Map<string, string>, errataTex: Map<string, [string, string]>}}
 */
const state = {
  catalog: [],
  entry: null,
  curve: null,
  controller: null,
  hidden: new Set(),
  smooth: {},
  surfaces: [],
  figures: [],
  katex: null,
  compare: {},
  claimTex: new Map(),
  errataTex: new Map(),
};

/** The discretization shown (set by selectDiscretization before anything reads it). @returns {Entry} */
function currentEntry() {
  if (!state.entry) throw new Error('no discretization is selected');
  return state.entry;
}

/**
 * @template {keyof HTMLElementTagNameMap} K
 * @param {K} tag
 * @param {Record<string, string | number | boolean | null | undefined>} [attributes]
 * @param {string | null} [text]
 * @returns {HTMLElementTagNameMap[K]}
 */
function html(tag, attributes = {}, text = null) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) {
    if (value === false || value === null || value === undefined) continue;
    node.setAttribute(key, value === true ? '' : String(value));
  }
  if (text !== null) node.textContent = text;
  return node;
}

// TeX from the API typeset by KaTeX (vendored, loaded on first use); the plain text stands in
// until KaTeX has loaded, and for good if it cannot be.
/** @param {string | null | undefined} tex @param {string} text @param {boolean} [display] */
function math(tex, text, display = false) {
  const node = html('span', { class: display ? 'math display' : 'math' });
  if (tex && state.katex) {
    try {
      state.katex.render(tex, node, { throwOnError: true, displayMode: display, strict: 'ignore', output: 'htmlAndMathml' });
      node.dataset.tex = tex;
      return node;
    } catch (error) {
      node.dataset.texError = String(thrown(error, 'message') || error);
    }
  }
  node.textContent = text;
  return node;
}

// KaTeX's minified build (a classic script from this origin, as the page's CSP allows): half the
// size of its ES module.
/** @param {string} src @returns {Promise<unknown>} */
function loadScript(src) {
  return new Promise((resolve, reject) => {
    const script = html('script', { src });
    script.addEventListener('load', resolve);
    script.addEventListener('error', () => reject(new Error(`${src} did not load`)));
    document.head.append(script);
  });
}

async function loadKatex() {
  try {
    await loadScript('/static/vendor/katex/dist/katex.min.js');
    state.katex = /** @type {Window & {katex?: Katex}} */ (window).katex || null;
  } catch {
    state.katex = null; // not built (make assets): the plain text stays
  }
}

// GET /theorems carries each statement's claim and each erratum as TeX.
async function loadStatementTex() {
  /** @type {Statement[]} */
  let statements = [];
  try { statements = await getJSON('/theorems'); } catch { return; }
  for (const statement of statements) {
    if (statement.claim_tex) state.claimTex.set(statement.id, statement.claim_tex);
    for (const erratum of statement.errata_tex || []) state.errataTex.set(erratum.id, [erratum.printed_tex, erratum.corrected_tex]);
  }
}

// The answer's type is the caller's (the generated type of the endpoint it asks).
/**
 * @template T
 * @param {string} url
 * @returns {Promise<T>}
 */
async function getJSON(url) {
  const response = await fetch(url, { headers: { Accept: 'application/json' } });
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return response.json();
}

// ---- the parameter form, built from the catalog ------------------------------------------------

/** @param {Parameter} parameter @returns {FieldSchema} */
function schemaOf(parameter) {
  const schema = /** @type {FieldSchema} */ (parameter.json_schema || {});
  if (schema.anyOf) {
    const concrete = schema.anyOf.find((s) => s.type !== 'null') || {};
    return { ...concrete, ...schema, anyOf: undefined, nullable: true };
  }
  return schema;
}

/** @param {Parameter} parameter */
function defaultText(parameter) {
  const value = parameter.default;
  if (value === null || value === undefined) return '';
  if (Array.isArray(value)) return value.join(', ');
  return String(value);
}

/** @param {Parameter} parameter */
function fieldKind(parameter) {
  const schema = schemaOf(parameter);
  if (schema.enum) return 'enum';
  if (schema.type === 'boolean') return 'boolean';
  if (schema.type === 'array') return 'array';
  if (schema.type === 'integer') return 'integer';
  if (schema.type === 'number') return 'number';
  return 'text';
}

/** @param {Parameter} parameter @param {string} [initial] the value from the shared URL */
function buildField(parameter, initial) {
  const name = parameter.name;
  const kind = fieldKind(parameter);
  const id = `param-${name}`;
  const wrap = html('div', { class: `field ${kind === 'boolean' ? 'checkbox' : ''}`, 'data-parameter': name });
  const help = html('p', { class: 'domain', id: `help-${name}` });
  if (parameter.domain) help.append(math(parameter.domain_tex, parameter.domain), ' — ');
  help.append(parameter.description || '');
  const error = html('p', { class: 'field-error', id: `error-${name}`, hidden: true, role: 'alert' });
  /** @type {Field} */
  let input;
  if (kind === 'enum') {
    const select = html('select', { id, name });
    for (const option of schemaOf(parameter).enum ?? []) select.append(html('option', { value: option }, String(option)));
    select.value = initial ?? defaultText(parameter);
    input = select;
  } else if (kind === 'boolean') {
    const box = html('input', { id, name, type: 'checkbox' });
    box.checked = initial !== undefined ? initial === 'true' : parameter.default === true;
    input = box;
  } else if (kind === 'array') {
    input = html('textarea', { id, name, rows: 3, placeholder: 'numbers separated by commas' });
    input.value = initial ?? defaultText(parameter);
  } else {
    input = html('input', {
      id, name, type: 'text', autocomplete: 'off', spellcheck: 'false',
      inputmode: kind === 'integer' ? 'numeric' : kind === 'number' ? 'decimal' : 'text',
      // an absent value has a meaning of its own (r = r*, j = 5, the default range): say so
      placeholder: parameter.default === null || parameter.default === undefined ? 'default (see below)' : null,
    });
    input.value = initial ?? defaultText(parameter);
  }
  input.setAttribute('aria-describedby', `help-${name} error-${name}`);
  input.dataset.kind = kind;
  input.dataset.default = kind === 'boolean' ? String(parameter.default === true) : defaultText(parameter);
  const label = html('label', { for: id }, name);
  if (kind === 'boolean') wrap.append(input, ' ', label, help, error);
  else {
    const range = (kind === 'number' || kind === 'integer') ? sliderRange(parameter) : null;
    if (range) {
      const slider = html('input', {
        type: 'range', id: `slider-${name}`, min: range.min, max: range.max, step: range.step,
        'aria-label': `${name}, slider from ${sliderText(range.min, range.step)} to ${sliderText(range.max, range.step)}`,
        'aria-describedby': `help-${name}`, 'data-slider': name,
      });
      const value = Number(input.value);
      slider.value = String(Number.isFinite(value) ? value : parameter.default);
      slider.addEventListener('input', (event) => {
        event.stopPropagation(); // not the form's debounced path: this one is live
        input.value = sliderText(slider.value, range.step);
        liveCompute();
      });
      slider.addEventListener('change', (event) => event.stopPropagation());
      input.addEventListener('input', () => { const v = Number(input.value); if (input.value.trim() !== '' && Number.isFinite(v)) slider.value = String(v); });
      const pair = html('div', { class: 'with-slider' });
      pair.append(input, slider);
      wrap.append(label, pair, help, error);
    } else {
      wrap.append(label, input, help, error);
    }
  }
  return wrap;
}

/** @param {Entry} entry @param {URLSearchParams} values */
function buildForm(entry, values) {
  const paper = $('paper-parameters');
  const common = $('common-parameters');
  for (const fieldset of [paper, common]) {
    for (const node of [...fieldset.children]) if (node.tagName !== 'LEGEND') node.remove();
  }
  for (const parameter of entry.parameters) {
    if (parameter.name === 'format') continue; // downloads choose the format
    const target = parameter.kind === 'common' ? common : paper;
    target.append(buildField(parameter, values.get(parameter.name) ?? undefined));
  }
  $('summary').textContent = entry.summary;
  $('reference').textContent = `Paper: ${entry.reference}`;
}

/** @returns {Field[]} */
function inputs() {
  return [.../** @type {NodeListOf<Field>} */ (document.querySelectorAll('#form [data-parameter] input:not([type="range"]), #form [data-parameter] select, #form [data-parameter] textarea'))];
}

// A slider's range for a number of the paper: the schema's bounds where they are close, else a
// range around the default (the service refuses what the domain excludes, and says so).
/** @param {Parameter} parameter @returns {{min: number, max: number, step: number} | null} */
function sliderRange(parameter) {
  const schema = schemaOf(parameter);
  const value = Number(parameter.default);
  if (parameter.kind !== 'paper' || !['number', 'integer'].includes(schema.type ?? '')) return null;
  if (parameter.default === null || parameter.default === undefined || !Number.isFinite(value)) return null;
  const lowBound = schema.minimum ?? schema.exclusiveMinimum;
  const highBound = schema.maximum ?? schema.exclusiveMaximum;
  if (schema.type === 'integer') {
    return { min: Math.max(lowBound ?? -Infinity, value - 40), max: Math.min(highBound ?? Infinity, value + 40), step: 1 };
  }
  let min, max;
  if (finite(lowBound) && finite(highBound) && highBound - lowBound <= 1e3) {
    [min, max] = [lowBound, highBound];
  } else if (finite(lowBound) && lowBound >= 0 && lowBound < value) {
    [min, max] = [lowBound, Math.max(10 * value, lowBound + 1)];
  } else {
    const spread = Math.max(4 * Math.abs(value), 1);
    [min, max] = [value - spread, value + spread];
  }
  const step = Number(((max - min) / 200).toPrecision(2));
  // an excluded end (0 < d) is not offered: the slider starts one step inside
  if (schema.exclusiveMinimum !== undefined && min === schema.exclusiveMinimum) min += step;
  if (schema.exclusiveMaximum !== undefined && max === schema.exclusiveMaximum) max -= step;
  return { min, max, step };
}

/** @param {number | string} value @param {number} step */
function sliderText(value, step) {
  const decimals = Math.max(0, -Math.floor(Math.log10(step)) + 1);
  return String(Number(Number(value).toFixed(decimals)));
}

// Dragging a slider computes as fast as the service answers: one request at a time, and the
// latest value once the one in flight has come back (no request is aborted half way).
const live = { running: false, again: false };
async function liveCompute() {
  if (live.running) { live.again = true; return; }
  live.running = true;
  try { await compute(); } finally {
    live.running = false;
    if (live.again) { live.again = false; liveCompute(); }
  }
}

// The parameters that differ from their defaults (what the request and the shared URL carry).
/** @returns {Changed[]} */
function changedValues() {
  /** @type {Changed[]} */
  const values = [];
  for (const input of inputs()) {
    const value = input.dataset.kind === 'boolean' ? String(/** @type {HTMLInputElement} */ (input).checked) : input.value.trim();
    if (value === '' || value === input.dataset.default) continue;
    values.push([input.name, value, input.dataset.kind ?? 'text']);
  }
  return values;
}

/**
 * The request for the form's values: a GET, or a POST with a JSON body when a list is given.
 * @param {Changed[]} values
 * @returns {{method: 'GET' | 'POST', url: string, query: URLSearchParams,
 *   body?: Record<string, string | number | boolean | number[]>}}
 */
function requestFor(values) {
  const id = currentEntry().id;
  const needsBody = values.some(([, , kind]) => kind === 'array');
  const query = new URLSearchParams(values.filter(([, , kind]) => kind !== 'array').map(([n, v]) => [n, v]));
  if (!needsBody) return { method: 'GET', url: `/discretizations/${id}?${query}`, query };
  /** @type {Record<string, string | number | boolean | number[]>} */
  const body = {};
  for (const [name, value, kind] of values) {
    if (kind === 'array') body[name] = value.split(/[\s,;]+/).filter(Boolean).map(Number);
    else if (kind === 'integer' || kind === 'number') body[name] = Number(value);
    else if (kind === 'boolean') body[name] = value === 'true';
    else body[name] = value;
  }
  return { method: 'POST', url: `/discretizations/${id}`, body, query };
}

// ---- errors from the API, shown by the field they name ----------------------------------------

function clearErrors() {
  for (const node of /** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll('.field-error'))) { node.hidden = true; node.textContent = ''; }
  for (const input of inputs()) input.removeAttribute('aria-invalid');
  $('form-error').hidden = true;
  $('form-error').textContent = '';
}

/** @param {ProblemText} problem @returns {number} how many errors were placed by their field */
function showProblem(problem) {
  let placed = 0;
  /** @type {string[]} */
  const unplaced = [];
  for (const error of problem.errors || []) {
    // "d", "s.3" (an entry of a list), "d4b.h" (a prefixed name): the first part that is a field
    const parts = String(error.parameter || '').split('.');
    const name = parts.find((part) => maybe(`param-${part}`)) || parts[0];
    const box = maybe(`error-${name}`);
    const input = maybe(`param-${name}`);
    const received = error.value === null || error.value === undefined ? '' : ` (received ${JSON.stringify(error.value)})`;
    const message = `${error.constraint}${received}`;
    if (box && input) {
      box.textContent = message;
      box.hidden = false;
      input.setAttribute('aria-invalid', 'true');
      placed += 1;
    } else {
      unplaced.push(`${error.parameter}: ${message}`);
    }
  }
  const box = $('form-error');
  const lines = [problem.title ? `${problem.title}: ${problem.detail || ''}` : String(problem.detail || 'Error')];
  if (unplaced.length) lines.push(...unplaced);
  box.textContent = lines.join(' ');
  box.hidden = false;
  return placed;
}

// ---- computing and drawing -------------------------------------------------------------------

/** @param {ReadonlyArray<readonly [number | string, number | string]>} points @returns {Point[]} */
function numbers(points) {
  return points.map(([x, y]) => [Number(x), Number(y)]);
}

/** The polygon p, its companions, the compared polygons and the smooth curves. @param {Curve} curve */
function curveSeries(curve) {
  /** @type {Series[]} */
  const series = [{ name: 'p', label: 'p — the discrete hyperbolic cosine', points: numbers(curve.vertices), color: PALETTE[0], width: 2 }];
  let k = 1;
  for (const [name, polyline] of Object.entries(curve.companions || {})) {
    series.push({ name, label: `${name} — ${polyline.description || ''}`, points: numbers(polyline.vertices), color: PALETTE[k % PALETTE.length], width: 1.2 });
    k += 1;
  }
  let c = 0;
  for (const [name, other] of Object.entries(state.compare)) {
    series.push({ name, label: other.label, points: other.points, color: COMPARE_COLOURS[c % COMPARE_COLOURS.length], dashed: true, width: 2.5 });
    c += 1;
  }
  for (const [name, smooth] of Object.entries(state.smooth)) {
    if (smooth.points) series.push({ name, label: smooth.label, points: smooth.points, color: '#555555', dashed: true, markers: false, width: 1.2 });
  }
  return series;
}

function drawPlot() {
  const plot = $('plot');
  if (!state.curve) return;
  const all = curveSeries(state.curve);
  const shown = all.filter((s) => !state.hidden.has(s.name));
  const width = widthFor(plot);
  plot.replaceChildren(plotSVG(shown, { title: state.curve.title, width, height: Math.round(width * 0.65) }));
  const layers = $('layers');
  for (const node of [...layers.children]) if (node.tagName !== 'LEGEND') node.remove();
  for (const s of all) {
    const id = `layer-${s.name}`;
    const label = html('label', { for: id });
    const box = html('input', { type: 'checkbox', id, 'data-layer': s.name });
    box.checked = !state.hidden.has(s.name);
    box.addEventListener('change', () => {
      if (box.checked) state.hidden.delete(s.name); else state.hidden.add(s.name);
      drawPlot();
      $(id).focus();
    });
    const swatch = html('span', { class: 'swatch', 'aria-hidden': 'true' });
    swatch.style.background = s.color;
    label.append(box, swatch, s.label);
    layers.append(label);
  }
}

/** @param {number | string | null | undefined} value */
function formatNumber(value) {
  if (value === null || value === undefined) return '—';
  if (typeof value === 'string') return value;
  if (value === 0) return '0';
  return Math.abs(value) < 1e-3 || Math.abs(value) >= 1e6 ? value.toExponential(2) : value.toPrecision(4);
}

/** @param {Curve} curve */
function drawChecks(curve) {
  const body = $tbody('checks-table');
  body.replaceChildren();
  let holds = 0, fails = 0, na = 0;
  for (const check of curve.checks) {
    const row = html('tr', { 'data-check': check.id });
    const statement = html('td');
    statement.append(html('strong', {}, check.id), html('br'), html('span', {}, check.reference));
    const tex = state.claimTex.get(check.id);
    if (tex) statement.append(html('div', { class: 'claim-tex' }, null));
    if (tex) /** @type {HTMLElement} */ (statement.lastChild).append(math(tex, ''));
    statement.append(html('div', { class: 'claim' }, check.claim));
    if (check.note) statement.append(html('div', { class: 'claim' }, `Note: ${check.note}`));
    const verdict = check.holds === true ? ['holds', '✓ holds'] : check.holds === false ? ['fails', '✗ fails'] : ['na', 'n/a'];
    if (check.holds === true) holds += 1; else if (check.holds === false) fails += 1; else na += 1;
    const erratum = html('td', { class: 'erratum' });
    if (check.erratum) {
      const e = check.erratum;
      const [printedTex, correctedTex] = state.errataTex.get(e.id) || [null, null];
      const sides = html('div', { class: 'erratum-sides' });
      const printed = html('div', { class: 'printed' });
      printed.append(html('span', { class: 'side' }, 'Printed'), math(printedTex, e.printed));
      const corrected = html('div', { class: 'corrected' });
      corrected.append(html('span', { class: 'side' }, 'Corrected'), math(correctedTex, e.corrected));
      sides.append(printed, corrected);
      erratum.append(html('strong', {}, e.id), sides,
        html('div', {}, `residual of the printed form: ${formatNumber(e.printed_residual)}`));
    }
    row.append(statement, html('td', { class: 'number' }, formatNumber(check.residual)),
      html('td', { class: 'number' }, formatNumber(check.tolerance)),
      html('td', { class: `verdict-${verdict[0]}` }, verdict[1]), erratum);
    body.append(row);
  }
  $('checks-summary').textContent = `${holds} hold, ${fails} fail, ${na} not applicable (${curve.precision.mode}, ${curve.precision.digits} digits).`;
  const constants = $('constants');
  constants.replaceChildren();
  const described = currentEntry().constants || {};
  for (const [name, value] of Object.entries(curve.constants || {})) {
    const dd = html('dd', {}, String(value));
    if (described[name]) dd.append(` — ${described[name]}`);
    const dt = html('dt', { title: described[name] || '' }, name);
    const tex = currentEntry().constants_tex?.[name];
    if (tex) dt.append(html('br'), math(tex, ''));
    constants.append(dt, dd);
  }
}

// The current values as a GET query: lists (a custom sequence s) comma-separated, as every GET
// endpoint accepts them.
function getQuery() {
  return new URLSearchParams(changedValues().map(([name, value, kind]) => [
    name, kind === 'array' ? value.split(/[\s,;]+/).filter(Boolean).join(',') : value]));
}

function updateDownloads() {
  const list = $('downloads');
  list.replaceChildren();
  const id = currentEntry().id;
  for (const format of ['json', 'csv', 'svg']) {
    const query = getQuery();
    query.set('format', format);
    const a = html('a', { href: `/discretizations/${id}?${query}`, download: `${id}.${format}`, 'data-format': format }, `${format.toUpperCase()} of this curve`);
    list.append(html('li', {}, null));
    /** @type {HTMLElement} */ (list.lastChild).append(a);
  }
}

// Nothing from a previous answer stays on the page once the parameters shown have no answer:
// the plot is marked stale, and the checks, constants, downloads and figures are emptied with a
// sentence saying why (what is shown always belongs to the parameters shown).
/** @param {string} reason */
function clearResult(reason) {
  state.curve = null;
  state.smooth = {};
  state.compare = {};
  $('compare-status').textContent = '';
  animation.update(null, getJSON); // no frames of the refused parameters' predecessor
  $('plot').classList.add('stale');
  $('plot').setAttribute('aria-describedby', 'status');
  $tbody('checks-table').replaceChildren();
  $('checks-summary').textContent = `No checks: ${reason}`;
  $('constants').replaceChildren();
  const downloads = $('downloads');
  downloads.replaceChildren(html('li', { class: 'hint', 'data-empty': 'true' }, `No downloads: ${reason}`));
  $('figure-list').replaceChildren();
  $('figures-note').textContent = `No figures: ${reason}`;
  $('overlay-status').textContent = '';
  document.body.dataset.result = 'none';
  for (const id of ['checks', 'share', 'figures']) $(id).removeAttribute('aria-busy');
}

function shareURL() {
  const query = new URLSearchParams([['id', currentEntry().id], ...changedValues().map(([n, v]) => [n, v])]);
  return `${location.pathname}?${query}`;
}

async function compute() {
  if (!state.entry) return;
  state.controller?.abort();
  const controller = new AbortController();
  state.controller = controller;
  clearErrors();
  const asked = JSON.stringify(changedValues());
  const request = requestFor(changedValues());
  $('status').textContent = 'Computing…';
  // until the answer comes, what is shown belongs to the previous parameters: say so
  for (const id of ['checks', 'share', 'figures']) $(id).setAttribute('aria-busy', 'true');
  document.body.dataset.result = 'pending';
  let response;
  try {
    response = await fetch(request.url, {
      method: request.method,
      headers: { Accept: 'application/json', ...(request.body ? { 'Content-Type': 'application/json' } : {}) },
      body: request.body ? JSON.stringify(request.body) : undefined,
      signal: controller.signal,
    });
  } catch (error) {
    if (thrown(error, 'name') === 'AbortError') return;
    $('status').textContent = `The service did not answer: ${messageOf(error)}`;
    clearResult('the service did not answer.');
    document.body.dataset.state = 'error';
    return;
  }
  if (controller !== state.controller) return;
  history.replaceState(null, '', shareURL());
  if (!response.ok) {
    /** @type {ProblemText} */
    let problem = { title: `HTTP ${response.status}`, detail: '', errors: [] };
    try { problem = await response.json(); } catch { /* not JSON */ }
    const placed = showProblem(problem);
    $('status').textContent = placed
      ? `Not computed: the service refused ${placed === 1 ? 'a value' : 'some values'} (see the marked field${placed === 1 ? '' : 's'}).`
      : `Not computed: ${problem.detail || problem.title}`;
    clearResult(placed ? 'the service refused the parameters above (see the marked field).' : `the request failed (${problem.detail || problem.title}).`);
    document.body.dataset.state = 'error';
    return;
  }
  /** @type {Curve} */
  let curve;
  try { curve = await response.json(); } catch (error) {
    $('status').textContent = `The answer could not be read: ${messageOf(error)}`;
    clearResult('the answer could not be read.');
    document.body.dataset.state = 'error';
    return;
  }
  if (controller !== state.controller) return;
  state.curve = curve;
  $('plot').classList.remove('stale');
  $('plot').removeAttribute('aria-describedby');
  // the fields may have moved on while this answer travelled (a slider): then it is not current
  document.body.dataset.query = request.query.toString();
  await loadSmooth(curve);
  await loadCompare(curve);
  drawPlot();
  await animation.update(curve, getJSON);
  drawChecks(curve);
  updateDownloads();
  updateFigures();
  const current = JSON.stringify(changedValues()) === asked;
  document.body.dataset.result = current ? 'current' : 'pending';
  if (current) for (const id of ['checks', 'share', 'figures']) $(id).removeAttribute('aria-busy');
  $('status').textContent = `${curve.title}: ${curve.vertices.length} vertices, indices ${curve.indices[0]} … ${curve.indices[curve.indices.length - 1]}.`;
  document.body.dataset.state = 'ready';
  document.body.dataset.computed = String(Number(document.body.dataset.computed || 0) + 1);
}

// ---- compare: other discretizations overlaid, with constants matched where Section 4 relates
// them (the current polygon's fitted c of (D1) or (D3), its x-step and start heights) ----------

const COMPARE_COLOURS = ['#7B3294', '#A6611A', '#018571', '#D01C8B'];

/** @param {Curve} curve @param {number} index @returns {Point | null} */
function vertexAt(curve, index) {
  const k = curve.indices.indexOf(index);
  return k < 0 ? null : [Number(curve.vertices[k][0]), Number(curve.vertices[k][1])];
}

// The request that should redraw this polygon as (D1) or (D3), or null when nothing matches:
// (D1) from p_0, p_1 and its constant; (D3) from p_0 and its constant (both branches tried).
/**
 * @param {string} target @param {Curve} curve
 * @returns {{text: string, shift: number, queries: URLSearchParams[]} | null}
 */
function matchedRequests(target, curve) {
  const p0 = vertexAt(curve, 0), p1 = vertexAt(curve, 1);
  const range = [['i_min', String(curve.indices[0])], ['i_max', String(curve.indices[curve.indices.length - 1])]];
  if (!p0 || !p1 || curve.vertices.some((v) => typeof v[0] !== 'number')) return null;
  const delta = p1[0] - p0[0];
  const c = Number(curve.constants?.[target]);
  if (!(delta > 0) || !Number.isFinite(c)) return null;
  const common = [['c', String(c)], ['delta', String(delta)], ['y0', String(p0[1])], ...range];
  const text = `c = ${formatNumber(c)} (this polygon's constants.${target}), δ = ${formatNumber(delta)}, from p_0${target === 'd1' ? ' and p_1' : ''}`;
  if (target === 'd1') return { text, shift: p0[0], queries: [new URLSearchParams([...common, ['y1', String(p1[1])]])] };
  if (target === 'd3') return { text, shift: p0[0], queries: ['up', 'down'].map((b) => new URLSearchParams([...common, ['branch', b]])) };
  return null;
}

/** @param {Point[]} a @param {Point[]} b */
function distance(a, b) {
  if (a.length !== b.length) return Infinity;
  return Math.max(...a.map(([x, y], k) => Math.hypot(x - b[k][0], y - b[k][1])));
}

// The closest of the matched requests' answers is drawn; one refused (a D3 branch) does not
// hide another's answer.
/** @param {Curve} curve */
async function loadCompare(curve) {
  state.compare = {};
  const chosen = [.../** @type {NodeListOf<HTMLInputElement>} */ (document.querySelectorAll('#compare input:checked'))].map((box) => box.value);
  /** @type {string[]} */
  const notes = [];
  for (const id of chosen) {
    const matched = matchedRequests(id, curve);
    const queries = matched ? matched.queries : [new URLSearchParams()];
    /** @type {{points: Point[], gap: number, query: URLSearchParams} | null} */
    let best = null;
    /** @type {string | null} */
    let failure = null;
    for (const query of queries) {
      try {
        // an overlay draws the polygon alone: nothing else is computed for it (issue 12)
        /** @type {Curve} */
        const body = await getJSON(`/discretizations/${id}?${query}&checks=none&companions=none`);
        /** @type {Point[]} */
        const points = numbers(body.vertices).map(([x, y]) => [x + (matched ? matched.shift : 0), y]);
        const gap = distance(points, numbers(curve.vertices));
        if (!best || gap < best.gap) best = { points, gap, query };
      } catch (error) {
        failure ??= messageOf(error);
      }
    }
    if (!best) { notes.push(`${id}: not drawn (${failure ?? 'no answer'})`); continue; }
    const how = matched ? `${matched.text}${matched.queries.length > 1 ? `, branch=${best.query.get('branch')}` : ''}` : 'its own defaults';
    state.compare[`compare-${id}`] = { label: `${id} with ${how}`, points: best.points };
    const same = matched && best.gap <= 1e-9 * Math.max(1, ...curve.vertices.map(([, y]) => Math.abs(Number(y))));
    notes.push(`${id} (${how}): ${matched ? (same ? 'the same polygon' : `largest distance ${formatNumber(best.gap)}`) : 'not related by matched constants'}`);
  }
  $('compare-status').textContent = notes.join('; ');
}

function setupCompare() {
  const box = $('compare');
  for (const node of [...box.children]) if (node.tagName !== 'LEGEND') node.remove();
  for (const entry of state.catalog) {
    if (entry.id === currentEntry().id) continue;
    const id = `compare-${entry.id}`;
    const label = html('label', { for: id });
    const input = html('input', { type: 'checkbox', id, value: entry.id });
    input.addEventListener('change', async () => { if (state.curve) { await loadCompare(state.curve); drawPlot(); $(id).focus(); } });
    label.append(input, ` ${entry.id}`);
    box.append(label);
  }
  $('compare-status').textContent = '';
}

// ---- smooth references (/smooth/catenary, /smooth/tractrix), when the service has them ---------

/** @param {Curve} body GET /smooth/{catenary,tractrix} @returns {Point[] | null} */
function smoothPoints(body) {
  if (Array.isArray(body.vertices)) return numbers(body.vertices);
  return null;
}

// A polygon below the x-axis (D2a: p_i^y < 0) is compared with the mirrored catenary −h·cosh(x/h).
/** @param {Curve} curve */
function mirrored(curve) {
  return curve.vertices.every(([, y]) => Number(y) < 0);
}

/** @param {Curve} curve */
function overlayH(curve) {
  const typed = Number($input('overlay-h').value);
  if ($input('overlay-h').value.trim() !== '' && Number.isFinite(typed) && typed > 0) return typed;
  if (typeof curve.parameters.h === 'number') return curve.parameters.h;
  if (curve.constants.d3 !== undefined) return Number(Number(curve.constants.d3).toPrecision(12)); // c of (D3) is h for h·cosh(x/h)
  const lowest = Math.min(...curve.vertices.map(([, y]) => Math.abs(Number(y))));
  return Number(lowest.toPrecision(6)); // the height at the vertex of h·cosh(x/h)
}

/** @param {Curve} curve */
async function loadSmooth(curve) {
  state.smooth = {};
  const flip = mirrored(curve);
  /** @type {[string, string, boolean][]} */
  const wanted = [['catenary', flip ? 'mirrored smooth catenary −h·cosh(x/h)' : 'smooth catenary h·cosh(x/h)', true]];
  if (curve.companions?.tractrix) wanted.push(['tractrix', 'smooth tractrix', false]);
  const available = wanted;
  $('overlay').hidden = false;
  const h = overlayH(curve);
  if ($input('overlay-h').value.trim() === '') $input('overlay-h').placeholder = String(h);
  const xs = curve.vertices.map(([x]) => Number(x));
  const [xMin, xMax] = [Math.min(...xs), Math.max(...xs)];
  /** @type {string[]} */
  const notes = [];
  for (const [name, label] of available) {
    // GET /smooth/{catenary,tractrix}: h and the sampled range x_min … x_max, count samples
    const query = new URLSearchParams([['h', String(h)], ['x_min', String(xMin)], ['x_max', String(xMax)], ['count', '200']]);
    try {
      /** @type {Curve} */
      const body = await getJSON(`/smooth/${name}?${query}`);
      let points = smoothPoints(body);
      if (points && flip) points = points.map(([x, y]) => [x, -y]);
      if (points) state.smooth[`smooth-${name}`] = { label: `${label}, h = ${h}`, points };
      else notes.push(`${name}: unexpected response shape`);
    } catch (error) {
      notes.push(`${name}: ${messageOf(error)}`);
    }
  }
  const how = flip ? ' and mirrored in the x-axis, as this polygon lies below it' : '';
  $('overlay-status').textContent = notes.length ? `Overlay not drawn — ${notes.join('; ')}` : `Drawn with h = ${h} (from GET /smooth/…)${how}.`;
}

// ---- surfaces (GET /surfaces/{id}?format=glb), when the service has them ------------------------

// GET /surfaces lists the meshes; each takes the surface's own parameters, the discretization
// giving the meridian and that discretization's parameters (the form's).
/** @param {Surface} surface @param {string} format */
function surfaceURL(surface, format) {
  const query = new URLSearchParams([['discretization', currentEntry().id]]);
  for (const [name, value] of getQuery()) if (!['format', 'detail'].includes(name)) query.set(name, value);
  query.set('format', format);
  return `${surface.url}?${query}`;
}

async function setupSurfaces() {
  try { state.surfaces = await getJSON('/surfaces'); } catch { state.surfaces = []; }
  const select = $select('surface');
  select.replaceChildren();
  if (!state.surfaces.length) {
    $('surface-status').textContent = 'The 3D view needs GET /surfaces, which this service does not offer.';
    return;
  }
  for (const surface of state.surfaces) select.append(html('option', { value: surface.id }, surface.id));
  select.disabled = false;
  $button('show-3d').disabled = false;
  $('surface-status').textContent = `${state.surfaces.length} surface${state.surfaces.length === 1 ? '' : 's'} available.`;
  select.addEventListener('change', updateSurfaceDownloads);
  updateSurfaceDownloads();
}

function updateSurfaceDownloads() {
  const list = $('surface-downloads');
  list.replaceChildren();
  const surface = state.surfaces.find((s) => s.id === $select('surface').value);
  if (!surface) return;
  for (const format of ['json', 'obj', 'ply', 'glb']) {
    const li = html('li');
    li.append(html('a', { href: surfaceURL(surface, format), download: `${surface.id}.${format}`, 'data-format': format }, `${format.toUpperCase()} of ${surface.id}`));
    list.append(li);
  }
}

async function show3D() {
  const surface = state.surfaces.find((s) => s.id === $select('surface').value);
  if (!surface) return;
  const status = $('surface-status');
  status.textContent = 'Loading the 3D view…';
  let view;
  try {
    view = await import('./view3d.js');
  } catch (error) {
    status.textContent = `The 3D view is unavailable: three.js was not built into /static/vendor (run make assets). ${messageOf(error)}`;
    return;
  }
  const response = await fetch(surfaceURL(surface, 'glb'));
  if (!response.ok) {
    /** @type {Partial<ProblemText>} */
    let problem = {};
    try { problem = await response.json(); } catch { /* not JSON */ }
    // no stale picture under a refusal: the old surface and its legend go
    $('view3d').hidden = true;
    $('view3d-keys').hidden = true;
    $('colour-legend').textContent = '';
    const named = (problem.errors || []).map((e) => `${e.parameter}: ${e.constraint}`).join('; ');
    status.textContent = `No ${surface.id} for ${currentEntry().id}: ${named || problem.detail || `HTTP ${response.status}`}.`;
    document.body.dataset.surface = 'error';
    return;
  }
  const container = $('view3d');
  container.hidden = false;
  $('view3d-keys').hidden = false;
  try {
    const info = await view.showSurface(container, await response.arrayBuffer(), $select('colour-by').value);
    $('colour-legend').textContent = info.legend;
    status.textContent = `${surface.id}: ${info.triangles} triangles. Drag or use the arrow keys to rotate.`;
    document.body.dataset.surface = 'ready';
    updateSurfaceDownloads();
  } catch (error) {
    status.textContent = `The surface could not be drawn: ${messageOf(error)}`;
  }
}

// ---- figures --------------------------------------------------------------------------------

// A figure follows the form: the values that differ from their defaults and that the figure
// also takes (same names, same domains) go into its URL.
/** @param {Figure} figure */
function figureURL(figure) {
  const names = new Set(figure.parameters.map((p) => p.name));
  const query = new URLSearchParams([...getQuery()].filter(([name]) => names.has(name)));
  const text = query.toString();
  return text ? `${figure.url}?${text}` : figure.url;
}

/** @param {Figure} figure @param {string} url */
function figureItem(figure, url) {
  const li = html('li', { 'data-figure': figure.id });
  const link = html('a', { href: url, class: 'figure-frame' });
  const img = html('img', { src: url, alt: figure.title, decoding: 'async', width: 800, height: 640 });
  const caption = html('p', {}, `${figure.title} (${figure.reference})`);
  const problem = html('p', { class: 'field-error', hidden: true, role: 'alert' });
  img.addEventListener('error', async () => {
    let detail = 'the figure could not be drawn';
    try { detail = (await (await fetch(url)).json()).detail || detail; } catch { /* not JSON */ }
    img.hidden = true; // no broken-image icon: the message says it
    problem.textContent = `Not drawn with these parameters: ${detail}`;
    problem.hidden = false;
    li.dataset.state = 'error';
  });
  img.addEventListener('load', () => {
    // a figure in several panels keeps a readable size on a phone: it scrolls sideways instead
    if (img.naturalWidth > 2 * img.naturalHeight) img.classList.add('wide');
    li.dataset.state = 'ready';
  });
  link.append(img);
  li.append(link, caption, problem);
  return li;
}

function updateFigures() {
  if (!state.entry) return;
  const entry = state.entry;
  const own = state.figures.filter((f) => (f.discretizations || []).includes(entry.id));
  const list = $('figure-list');
  const wanted = own.map((f) => /** @type {[Figure, string]} */ ([f, figureURL(f)]));
  const shown = [...list.querySelectorAll('li')].map((li) => li.querySelector('a')?.getAttribute('href'));
  if (JSON.stringify(shown) !== JSON.stringify(wanted.map(([, url]) => url))) {
    list.replaceChildren(...wanted.map(([f, url]) => figureItem(f, url)));
  }
  $('figures-note').textContent = own.length
    ? `The paper's figure${own.length === 1 ? '' : 's'} of ${state.entry.id}, drawn with the parameters above that ${own.length === 1 ? 'it takes' : 'they take'} (${own.length === 1 ? 'its' : 'their'} own defaults for the rest).`
    : `The paper has no figure of ${state.entry.id}; the others are below.`;
  const others = $('all-figures');
  if (!others.children.length) {
    for (const figure of state.figures) {
      const li = html('li', { 'data-figure': figure.id });
      const a = html('a', { href: figure.url }, figure.title);
      li.append(a, html('span', { class: 'hint' }, ` — ${figure.reference}`));
      others.append(li);
    }
  }
}

async function setupFigures() {
  try { state.figures = await getJSON('/figures'); } catch { state.figures = []; }
  updateFigures();
}

// ---- start ----------------------------------------------------------------------------------

const animation = new Animation({
  section: $('animation'), title: $('animation-title'), plot: $('animation-plot'), play: $button('anim-play'),
  back: $button('anim-back'), forward: $button('anim-forward'), slider: $input('anim-frame'), text: $('anim-text'),
});

/** @type {ReturnType<typeof setTimeout> | undefined} */
let timer;
function scheduleCompute() {
  clearTimeout(timer);
  timer = setTimeout(compute, 350);
}

/** @param {string} id @param {URLSearchParams} [values] from the shared URL */
function selectDiscretization(id, values = new URLSearchParams()) {
  state.entry = state.catalog.find((e) => e.id === id) || state.catalog[0];
  $select('discretization').value = state.entry.id;
  state.hidden.clear();
  state.compare = {};
  buildForm(state.entry, values);
  setupCompare();
}

async function start() {
  try {
    [state.catalog] = await Promise.all([/** @type {Promise<Entry[]>} */ (getJSON('/discretizations')), loadKatex()]);
  } catch (error) {
    $('status').textContent = `The catalog could not be loaded: ${messageOf(error)}`;
    return;
  }
  const select = $select('discretization');
  for (const entry of state.catalog) select.append(html('option', { value: entry.id }, `${entry.id} — ${entry.title}`));
  const params = new URLSearchParams(location.search);
  // Wunderlich's (D4b) opens first: the construction the paper proves the most about
  const opening = state.catalog.some((e) => e.id === 'd4b') ? 'd4b' : state.catalog[0].id;
  selectDiscretization(params.get('id') || opening, params);

  select.addEventListener('change', () => { selectDiscretization(select.value); compute(); });
  const form = $('form');
  form.addEventListener('submit', (event) => { event.preventDefault(); clearTimeout(timer); compute(); });
  form.addEventListener('input', (event) => { if (event.target !== select) scheduleCompute(); });
  form.addEventListener('change', (event) => { if (event.target !== select) { clearTimeout(timer); compute(); } });
  $('defaults').addEventListener('click', () => { selectDiscretization(currentEntry().id); compute(); });
  $('copy-link').addEventListener('click', async () => {
    const url = new URL(shareURL(), location.href).href;
    try { await navigator.clipboard.writeText(url); $('copy-status').textContent = 'Copied.'; } catch { $('copy-status').textContent = url; }
  });
  $('overlay-h').addEventListener('change', async () => { if (state.curve) { await loadSmooth(state.curve); drawPlot(); } });
  $('show-3d').addEventListener('click', show3D);
  $select('colour-by').addEventListener('change', () => { if (!$('view3d').hidden) show3D(); });
  await Promise.all([setupSurfaces(), setupFigures()]);
  await compute();
  // the typeset claims and errata come after the first plot, then the checks are drawn again
  await loadStatementTex();
  if (state.curve) drawChecks(state.curve);
  document.body.dataset.tex = state.katex ? 'ready' : 'unavailable';
}

start();
