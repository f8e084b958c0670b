// The studio page, panel.js. The side panel: the table, the model's fields and points, the view
// and key bindings, and its updates while a point is dragged (at most every PANEL_EVERY_MS).

import { fmt, syncViewControls } from './figures.js';
import { fitData } from './fitting.js';
import { propose } from './queue.js';
import { $, DEFAULT_CAMERA, OTHER_VIEWS, PAPER_VIEWS, clearFieldErrors, clone, redo, state, undo, updateButtons } from './state.js';

// The side panel (the table and the fields) while a point is dragged: at most every
// PANEL_EVERY_MS, and after the last frame; the views are redrawn every frame. Each update
// of the panel makes the browser lay it out and paint it again, which on a two-core machine
// took a third of a frame.
const PANEL_EVERY_MS = 100;
let panelAt = -Infinity;
let panelTimer = null;
let panelTable = null;

function updatePanel(table) {
  panelAt = performance.now();
  clearFieldErrors();
  drawTable(table);
  fillModelFields();
  updateButtons();
}

function schedulePanel(table) {
  panelTable = table;
  const wait = panelAt + PANEL_EVERY_MS - performance.now();
  if (wait <= 0) {
    clearTimeout(panelTimer);
    panelTimer = null;
    updatePanel(table);
  } else if (!panelTimer) {
    panelTimer = setTimeout(() => {
      panelTimer = null;
      updatePanel(panelTable);
    }, wait);
  }
}

// The panel at once (a settled answer); an update scheduled by a drag frame is dropped.
function updatePanelNow(table) {
  clearTimeout(panelTimer);
  panelTimer = null;
  updatePanel(table);
}

// ------------------------------------------------------------------------------------------
// Table

function cellText(cell) {
  const v = Number(cell);
  return Number.isFinite(v) ? String(Math.round(v * 1e6) / 1e6) : cell;
}

function drawTable(table) {
  const host = $('#table-host');
  if (!table) { host.innerHTML = ''; return; }
  if (table.error) {
    host.innerHTML = '';
    const p = document.createElement('p');
    p.className = 'field-error';
    p.textContent = table.error;
    host.appendChild(p);
    return;
  }
  // Same columns and row count: only the cells change (no new layout of the table).
  const old = host.querySelector('table');
  if (old && old.dataset.shape === `${table.columns.join(',')}/${table.rows.length}`) {
    const cells = old.tBodies[0].rows;
    table.rows.forEach((row, i) => row.forEach((cell, j) => {
      const text = cellText(cell);
      if (cells[i].cells[j].textContent !== text) cells[i].cells[j].textContent = text;
    }));
    return;
  }
  host.innerHTML = '';
  const t = document.createElement('table');
  t.dataset.shape = `${table.columns.join(',')}/${table.rows.length}`;
  // Many columns (a wide family's channels): a smaller font, and the names broken after
  // their underscores (truth_ / lower), so that the table fits the panel or nearly.
  t.classList.toggle('many', table.columns.length > 6);
  const head = t.createTHead().insertRow();
  for (const c of table.columns) {
    const th = document.createElement('th');
    c.split(/(?<=_)/).forEach((part, i) => {
      if (i > 0) th.appendChild(document.createElement('wbr'));
      th.appendChild(document.createTextNode(part));
    });
    head.appendChild(th);
  }
  const body = t.createTBody();
  for (const row of table.rows) {
    const tr = body.insertRow();
    for (const cell of row) tr.insertCell().textContent = cellText(cell);
  }
  host.appendChild(t);
}

// ------------------------------------------------------------------------------------------
// Model fields

function selectPoint(k, redraw) {
  state.selected = k;
  fillModelFields(true);
  document.querySelectorAll('[data-point-index]').forEach((h) => {
    h.classList.toggle('selected', Number(h.getAttribute('data-point-index')) === k);
  });
  if (redraw) clearFieldErrors();
}

function setValue(input, value, force) {
  if (!force && document.activeElement === input) return;
  if (!force && input.classList.contains('invalid')) return;
  put(input, 'value', value === undefined || value === null ? '' : String(value));
}

// Sets a property only when it changes: a drag redraws many times a second, and every
// write to the page, even of the same value, may make the browser lay it out again.
function put(element, property, value) {
  if (element[property] !== value) element[property] = value;
}

function knotsText(knots) {
  if (knots === undefined) return '';
  return Array.isArray(knots) ? knots.join(', ') : String(knots);
}

function fillModelFields(force) {
  const m = state.model;
  if (!m) return;
  setValue($('#model-name'), m.name || '', force);
  setValue($('#model-description'), m.description || '', force);
  put($('#model-kind'), 'value', m.kind);
  const surface = m.kind.endsWith('surface');
  put($('#model-kind'), 'disabled', surface);
  setValue($('#model-degree'), m.degree, force);
  put($('#model-degree'), 'disabled', m.kind === 'bezier' || surface);
  setValue($('#model-knots'), knotsText(m.knots), force);
  put($('#model-knots'), 'disabled', !(m.kind === 'bspline' || m.kind === 'nurbs'));
  put($('#model-membership'), 'value', m.membership || 'neutrosophic');
  const n = m.control_points.length;
  const select = $('#point-index');
  if (select.options.length !== n) {
    select.innerHTML = '';
    m.control_points.forEach((p, k) => {
      const o = document.createElement('option');
      o.value = String(k);
      o.textContent = p.name ? `${k}: ${p.name}` : String(k);
      select.appendChild(o);
    });
  }
  m.control_points.forEach((p, k) => {
    const label = p.name ? `${k}: ${p.name}` : String(k);
    if (select.options[k].textContent !== label) select.options[k].textContent = label;
  });
  if (state.selected >= n) state.selected = n - 1;
  put(select, 'value', String(state.selected));
  const p = m.control_points[state.selected];
  const fields = $('#point-fields');
  for (const key of ['x', 'y', 'z', 'weight']) {
    setValue(fields.querySelector(`input[name=${key}]`), p[key], force);
  }
  put($('#z-field'), 'hidden', p.z === undefined);
  put($('#weight-field'), 'hidden', m.kind !== 'nurbs' && m.kind !== 'nurbs-surface');
  fillDegreeFields(p, force);
  const curve = !surface;
  put($('#add-point'), 'disabled', !curve);
  put($('#insert-point'), 'disabled', !curve);
  put($('#delete-point'), 'disabled', !curve || n <= 2);
}

// ------------------------------------------------------------------------------------------
// Degree fields: one field and slider per degree of the model's family, as the server
// describes it (`family.fields`: name, min, max, derived; `family.rule`), so that the page
// holds no knowledge of the families. A derived field (a degree slot a family of one lane
// does not carry: the intuitionistic hesitation, else 0) is shown disabled, with the value the
// server gives (`pointDegrees`).

// A value shown in a field: rounded to 12 decimals (1 - 0.8 - 0.1 shows as 0.1).
function shownNumber(v) {
  return typeof v === 'number' ? Math.round(v * 1e12) / 1e12 : v;
}

// The colour of a degree's name: truth, indeterminacy or falsity, whatever its bound or sign.
function tone(name) {
  return name.replace(/^negative_/, '').replace(/_(lower|upper)$/, '');
}

let degreeLayout = '';

// Builds the rows of `fields` unless they are the rows shown.
function buildDegreeFields(fields) {
  const layout = JSON.stringify(fields.map((f) => [f.name, f.min, f.max]));
  if (layout === degreeLayout) return;
  degreeLayout = layout;
  const host = $('#degree-fields');
  host.innerHTML = '';
  for (const f of fields) {
    const row = document.createElement('div');
    row.className = 'degree';
    row.dataset.degree = f.name;
    row.dataset.tone = tone(f.name);
    const label = document.createElement('span');
    label.className = 'degree-name';
    label.textContent = f.name;
    const slider = document.createElement('input');
    Object.assign(slider, { type: 'range', min: String(f.min), max: String(f.max), step: '0.01' });
    slider.dataset.slider = f.name;
    slider.setAttribute('aria-label', `${f.name} slider`);
    const input = document.createElement('input');
    Object.assign(input, { name: f.name, type: 'number', step: '0.01', min: String(f.min), max: String(f.max) });
    input.setAttribute('aria-label', f.name);
    const error = document.createElement('span');
    error.className = 'field-error';
    error.dataset.errorFor = f.name;
    row.append(label, slider, input, error);
    host.appendChild(row);
    input.addEventListener('change', () => {
      input.classList.remove('invalid');
      editPoint(f.name, numberOrText(input.value), true);
    });
    slider.addEventListener('input', () => editPoint(f.name, Number(slider.value), false));
    slider.addEventListener('change', () => editPoint(f.name, Number(slider.value), true));
  }
}

function fillDegreeFields(p, force) {
  const family = state.family;
  if (!family) return;
  buildDegreeFields(family.fields);
  const fields = $('#degree-fields');
  const shown = state.pointDegrees[state.selected] || [];
  family.fields.forEach((f, i) => {
    const input = fields.querySelector(`input[name=${f.name}]`);
    const slider = fields.querySelector(`input[data-slider=${f.name}]`);
    const value = f.derived || p[f.name] === undefined ? shownNumber(shown[i]) : p[f.name];
    put(input, 'disabled', f.derived);
    put(slider, 'disabled', f.derived);
    setValue(input, value, force);
    if (document.activeElement !== slider) put(slider, 'value', String(value === undefined ? 0 : value));
  });
  put($('#rule-note'), 'textContent', family.rule);
}

// The membership list: every family the server describes.
function fillFamilies(families) {
  state.families = families;
  const select = $('#model-membership');
  select.innerHTML = '';
  for (const f of families) {
    const o = document.createElement('option');
    o.value = f.name;
    o.textContent = f.label;
    select.appendChild(o);
  }
  if (state.model) put(select, 'value', state.model.membership || 'neutrosophic');
}

// A typed value: a finite number, or the text itself so that the server names it.
function numberOrText(text) {
  const t = String(text).trim();
  const v = Number(t);
  return t !== '' && Number.isFinite(v) ? v : t;
}

// After the number of points or the degree changes: Bézier degree n - 1; spline knots back
// to clamped uniform (the server writes them out).
function reshape(m) {
  const n = m.control_points.length;
  if (m.kind === 'bezier') m.degree = n - 1;
  if (m.kind === 'bspline' || m.kind === 'nurbs') {
    if (typeof m.degree === 'number' && m.degree > n - 1) m.degree = Math.max(1, n - 1);
    m.knots = 'clamped-uniform';
  }
  return m;
}

function editPoint(key, value, commit) {
  const m = clone(state.model);
  m.control_points[state.selected][key] = value;
  propose(m, {
    commit,
    message: commit ? `point ${state.selected}: ${key} = ${value}` : '',
    coalesce: !commit,
    preview: !commit,
    field: key,
  });
}

function attachFields() {
  const fields = $('#point-fields');
  for (const key of ['x', 'y', 'z', 'weight']) {
    const input = fields.querySelector(`input[name=${key}]`);
    input.addEventListener('change', () => {
      input.classList.remove('invalid');
      editPoint(key, numberOrText(input.value), true);
    });
  }
  $('#point-index').addEventListener('change', (e) => selectPoint(Number(e.target.value), true));
  $('#model-name').addEventListener('change', (e) => {
    const m = clone(state.model);
    if (e.target.value.trim() === '') delete m.name; else m.name = e.target.value;
    propose(m, { commit: true, message: 'name changed' });
  });
  $('#model-description').addEventListener('change', (e) => {
    const m = clone(state.model);
    if (e.target.value.trim() === '') delete m.description; else m.description = e.target.value;
    propose(m, { commit: true, message: 'description changed' });
  });
  $('#model-kind').addEventListener('change', (e) => setKind(e.target.value));
  $('#model-degree').addEventListener('change', (e) => {
    const m = clone(state.model);
    m.degree = numberOrText(e.target.value);
    if (m.kind === 'bspline' || m.kind === 'nurbs') m.knots = 'clamped-uniform';
    propose(m, { commit: true, message: `degree ${e.target.value} (knots clamped uniform)` });
  });
  $('#model-knots').addEventListener('change', (e) => {
    const m = clone(state.model);
    const text = e.target.value.trim();
    if (['clamped-uniform', 'chord-length', 'centripetal'].includes(text)) m.knots = text;
    else m.knots = text.split(/[\s,]+/).filter((s) => s !== '').map(numberOrText);
    propose(m, { commit: true, message: 'knots changed' });
  });
  $('#model-membership').addEventListener('change', (e) => setMembership(e.target.value));
  $('#add-point').addEventListener('click', () => addPoint(false));
  $('#insert-point').addEventListener('click', () => addPoint(true));
  $('#delete-point').addEventListener('click', deletePoint);
}

function setKind(kind) {
  const m = clone(state.model);
  const n = m.control_points.length;
  if (kind === 'bezier') {
    delete m.knots;
    m.degree = n - 1;
    m.control_points.forEach((p) => { delete p.weight; });
  } else {
    m.degree = m.kind === 'bezier' ? Math.max(1, Math.min(3, n - 1)) : Math.min(m.degree, n - 1);
    m.knots = 'clamped-uniform';
    m.control_points.forEach((p) => {
      if (kind === 'nurbs') { if (p.weight === undefined) p.weight = 1; } else delete p.weight;
    });
  }
  m.kind = kind;
  propose(m, { commit: true, message: `kind: ${kind}, degree ${m.degree}` });
}

// Switches the model to the family `name`, converting every point's degrees by channel name
// (the server's descriptions of both families): a channel of both is kept (a derived degree
// slot of the old family counts as shown, so the intuitionistic hesitation becomes the
// indeterminacy); `X_lower` and `X_upper` start at `X` (a degenerate interval); `X` starts at
// the midpoint of `X_lower` and `X_upper`; any other channel (the bipolar negative degrees
// among them) at 0. A family with a parameter keeps the model's, else gets the server's.
function setMembership(name) {
  const to = state.families.find((f) => f.name === name);
  const from = state.family;
  if (!to || !from) return;
  const m = clone(state.model);
  const everyChannel = new Set(state.families.flatMap((f) => f.channels.map((c) => c.name)));
  m.control_points.forEach((p, k) => {
    const shown = state.pointDegrees[k] || [];
    const old = {};
    from.fields.forEach((f, i) => { if (typeof shown[i] === 'number') old[f.name] = shownNumber(shown[i]); });
    for (const c of from.channels) if (typeof p[c.name] === 'number') old[c.name] = p[c.name];
    for (const key of Object.keys(p)) if (everyChannel.has(key)) delete p[key];
    for (const c of to.channels) p[c.name] = converted(old, c.name);
  });
  const key = to.parameter ? to.parameter.key : null;
  for (const f of state.families) {
    if (f.parameter && f.parameter.key !== key) delete m[f.parameter.key];
  }
  if (key) m[key] = m[key] || to.parameter.value;
  m.membership = name;
  propose(m, { commit: true, message: `membership: ${name}` });
}

// Channel `name` from the values `old` of another family's channels (see setMembership).
function converted(old, name) {
  if (old[name] !== undefined) return old[name];
  const bound = /^(.*)_(lower|upper)$/.exec(name);
  if (bound && old[bound[1]] !== undefined) return old[bound[1]];
  const [lower, upper] = [old[`${name}_lower`], old[`${name}_upper`]];
  if (lower !== undefined && upper !== undefined) return shownNumber((lower + upper) / 2);
  return 0;
}

function addPoint(insert) {
  const m = clone(state.model);
  const pts = m.control_points;
  const n = pts.length;
  let at;
  let p;
  if (insert && n >= 2) {
    const k = Math.min(state.selected, n - 2);
    const a = pts[k];
    const b = pts[k + 1];
    p = {};
    for (const key of Object.keys(a)) {
      if (key === 'name') continue;
      p[key] = typeof a[key] === 'number' && typeof b[key] === 'number' ? (a[key] + b[key]) / 2 : a[key];
    }
    at = k + 1;
  } else {
    const last = pts[n - 1];
    const prev = n >= 2 ? pts[n - 2] : null;
    p = {};
    for (const key of Object.keys(last)) {
      if (key === 'name') continue;
      p[key] = last[key];
    }
    for (const key of ['x', 'y', 'z']) {
      if (last[key] === undefined) continue;
      p[key] = prev ? 2 * last[key] - prev[key] : last[key] + 1;
    }
    at = n;
  }
  pts.splice(at, 0, p);
  reshape(m);
  state.selected = at;
  propose(m, { commit: true, message: `point ${at} added` });
}

function deletePoint() {
  const m = clone(state.model);
  if (m.control_points.length <= 2) return;
  const k = state.selected;
  m.control_points.splice(k, 1);
  reshape(m);
  state.selected = Math.max(0, k - 1);
  propose(m, { commit: true, message: `point ${k} deleted` });
}

// ------------------------------------------------------------------------------------------
// Views, table and keys

function attachViews() {
  const toggles = $('#view-toggles');
  const large = $('#large-view');
  const exportView = $('#export-view');
  for (const view of PAPER_VIEWS.concat(OTHER_VIEWS)) {
    const label = document.createElement('label');
    label.innerHTML = `<input type="checkbox" value="${view}"> ${view}`;
    toggles.appendChild(label);
    for (const select of [large, exportView]) {
      const o = document.createElement('option');
      o.value = view;
      o.textContent = view;
      select.appendChild(o);
    }
  }
  exportView.value = 'plane';
  toggles.addEventListener('change', (e) => {
    state.shown[e.target.value] = e.target.checked;
    syncViewControls();
    propose(null);
  });
  $('#layout').addEventListener('change', (e) => { state.layout = e.target.value; syncViewControls(); propose(null); });
  large.addEventListener('change', (e) => { state.large = e.target.value; syncViewControls(); propose(null); });
  $('#reset-camera').addEventListener('click', () => { state.camera = clone(DEFAULT_CAMERA); propose(null, { message: 'camera reset' }); });
  $('#table-at').addEventListener('change', (e) => { state.at = e.target.value; propose(null); });
  $('#color-by').addEventListener('change', (e) => { state.colorBy = e.target.value; propose(null); });
  $('#fit').addEventListener('click', fitData);
}

function typing(target) {
  if (!target || !target.tagName) return false;
  if (target.tagName === 'TEXTAREA' || target.tagName === 'SELECT') return true;
  return target.tagName === 'INPUT' && target.type !== 'range' && target.type !== 'checkbox';
}

function attachKeys() {
  document.addEventListener('keydown', (e) => {
    const key = e.key.toLowerCase();
    if ((e.ctrlKey || e.metaKey) && (key === 'z' || key === 'y')) {
      if (typing(e.target)) return;
      e.preventDefault();
      if (key === 'y' || e.shiftKey) redo(); else undo();
      return;
    }
    const arrows = { arrowleft: [-1, 0], arrowright: [1, 0], arrowup: [0, 1], arrowdown: [0, -1] };
    if (key in arrows && !typing(e.target) && state.model && state.handles && state.handles.frame) {
      e.preventDefault();
      const [dx, dy] = arrows[key];
      const [sx] = state.handles.frame;
      const step = (e.shiftKey ? 50 : 5) / Math.abs(sx);
      const m = clone(state.model);
      const p = m.control_points[state.selected];
      p.x += dx * step;
      p.y += dy * step;
      propose(m, { commit: true, message: `point ${state.selected} moved to (${fmt(p.x)}, ${fmt(p.y)})` });
    }
  });
}

export { updatePanel, updatePanelNow, schedulePanel, selectPoint, put, fillModelFields, fillFamilies, attachFields, attachViews, attachKeys };
