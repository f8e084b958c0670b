// The studio page, state.js. The page's state: the constants, the model and what is shown
// (`state`), the messages, and undo and redo (a stack of committed model texts).

import { put, selectPoint } from './panel.js';
import { propose } from './queue.js';

const PAPER_VIEWS = ['plane', 'controls', 'truth', 'indeterminacy', 'falsity', 'all'];
const OTHER_VIEWS = ['score', 'derived', 'data'];
const TURNABLE = ['truth', 'indeterminacy', 'falsity', 'all', 'score'];
const DEFAULT_CAMERA = { azimuth: -55, elevation: 25 };
const SVG_NS = 'http://www.w3.org/2000/svg';
const COORDINATES = ['x', 'y', 'z'];
// Samples along the curve while a point is dragged (the figure after the drag uses the
// plot's default, as exports do).
const PREVIEW_SAMPLES = 80;

const $ = (sel) => document.querySelector(sel);
const clone = (v) => JSON.parse(JSON.stringify(v));

const state = {
  model: null,          // the current (accepted) model, canonical JSON object
  committed: null,      // text of the last model in the undo history
  history: [],          // texts before each committed change
  future: [],
  file: null,
  canSave: false,
  selected: 0,
  shown: Object.fromEntries(PAPER_VIEWS.map((v) => [v, true]).concat(OTHER_VIEWS.map((v) => [v, false]))),
  refused: {},          // view -> why the model's family cannot draw it (from the server)
  layout: 'grid',
  large: 'plane',
  camera: clone(DEFAULT_CAMERA),
  at: '',
  data: null,           // {name, text}
  colorBy: 'truth',
  info: null,
  family: null,         // the server's description of the model's family (channels, rule, ...)
  families: [],         // the families the membership list offers, described by the server
  pointDegrees: [],     // the values of the family's degree fields at every control point
  handles: null,
  timings: [],          // one per drawn frame: {total, server, dom}
  renders: 0,
};

// ------------------------------------------------------------------------------------------
// Messages

function status(text) {
  $('#alert').textContent = '';
  $('#status').textContent = text;
}

function alertMessage(text) {
  $('#status').textContent = '';
  $('#alert').textContent = text;
}

function clearFieldErrors() {
  document.querySelectorAll('.field-error').forEach((e) => put(e, 'textContent', ''));
  document.querySelectorAll('input.invalid').forEach((e) => e.classList.remove('invalid'));
}

// The names of the degree fields the panel shows for the model's family.
function degreeNames() {
  return state.family ? state.family.fields.map((f) => f.name) : [];
}

// The field of a refusal (`control_points[1].truth`, `knots`, ...) -> the input next to which
// the message is shown. `edited`: the degree field whose edit was refused, preferred when the
// message names it (a rule over several channels names them all).
function showFieldError(field, message, detail, edited) {
  if (!field) return;
  const m = /^control_points\[(\d+)\]\.(\w+)/.exec(field);
  let key = field.split(/[.[]/)[0];
  const p = /^control_points\[(\d+)\]/.exec(field);
  if (p) {
    const index = Number(p[1]);
    if (index !== state.selected) selectPoint(index, false);
    // The reader names the point (`control_points[1]`) and the message the values
    // (`truth = 1.2 is outside ...`, `truth_lower = 0.6 exceeds truth_upper = 0.4 ...`,
    // `truth^2 + falsity^2 = 1.3 exceeds 1 ...`), or the field names both.
    const words = (detail || '').split(/[^A-Za-z_]+/);
    const named = degreeNames().filter((name) => words.includes(name));
    const leading = /^(\w+) = /.exec(detail || '');
    if (m) key = m[2];
    else if (named.includes(edited)) key = edited;
    else if (named.length) key = words.find((w) => named.includes(w));
    else key = leading ? leading[1] : 'position';
    const input = document.querySelector(`#point-fields input[name=${key}]`);
    if (input) input.classList.add('invalid');
    if (!degreeNames().includes(key)) key = 'position';
  }
  const slot = document.querySelector(`[data-error-for="${key}"]`);
  if (slot) slot.textContent = message;
}

// ------------------------------------------------------------------------------------------
// Undo and redo

function undo() {
  if (!state.history.length) { status('nothing to undo'); return; }
  state.future.push(state.committed);
  state.committed = state.history.pop();
  propose(JSON.parse(state.committed), { message: 'undone' });
}

function redo() {
  if (!state.future.length) { status('nothing to redo'); return; }
  state.history.push(state.committed);
  state.committed = state.future.pop();
  propose(JSON.parse(state.committed), { message: 'redone' });
}

function updateButtons() {
  put($('#undo'), 'disabled', !state.history.length);
  put($('#redo'), 'disabled', !state.future.length);
  put($('#save'), 'disabled', !state.canSave);
}

export { PAPER_VIEWS, OTHER_VIEWS, TURNABLE, degreeNames, DEFAULT_CAMERA, SVG_NS, COORDINATES, PREVIEW_SAMPLES, $, clone, state, status, alertMessage, clearFieldErrors, showFieldError, undo, redo, updateButtons };
