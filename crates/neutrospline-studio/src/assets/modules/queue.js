// The studio page, queue.js. The request queue: the one render request in flight, proposals that
// replace each other while it is, and applying an answer (figures, table, fields) once it arrives.

import { drawFigures, syncViewControls } from './figures.js';
import { fillModelFields, schedulePanel, updatePanelNow } from './panel.js';
import { $, OTHER_VIEWS, PAPER_VIEWS, PREVIEW_SAMPLES, alertMessage, clearFieldErrors, showFieldError, state, status } from './state.js';

// ------------------------------------------------------------------------------------------
// Server

async function post(path, body) {
  const response = await fetch(path, {
    method: 'POST',
    headers: { 'Content-Type': 'application/json' },
    body: JSON.stringify(body),
  });
  return response;
}

async function postJson(path, body) {
  const response = await post(path, body);
  let value = null;
  try { value = await response.json(); } catch (e) { value = { error: { message: `${response.status} ${response.statusText}` } }; }
  return { ok: response.ok, status: response.status, value };
}

// The figure's options go in `figure`, by the names of the plot crate's FigureRequest (those of
// `neutrospline plot`); the data beside them.
function extra(figure = {}) {
  return {
    data: state.data,
    figure: Object.assign({
      azimuth: state.camera.azimuth,
      elevation: state.camera.elevation,
      'color-by': state.colorBy,
    }, figure),
  };
}

// ------------------------------------------------------------------------------------------
// Rendering: one request at a time. Proposals made meanwhile replace each other, and the
// latest leaves as soon as the answer before it has been drawn. (Sending it as soon as the
// answer arrives, so that the server draws frame N + 1 while the page paints frame N,
// measured no faster on a two-core machine, where both compete for the same cores.)

let pending = null;
let serverBusy = false;
let outstanding = 0;  // requests sent whose answers are not applied yet
let applied = Promise.resolve();
let idleWaiters = [];

function shownViews() {
  if (state.layout === 'large') return [state.large];
  // A view the model's family cannot draw is not shown (its box is greyed out, the reason
  // its title).
  const refused = state.refused || {};
  return PAPER_VIEWS.concat(OTHER_VIEWS).filter((v) => state.shown[v] && !(v in refused));
}

// Proposes `model` (null: redraw the current one). `how.commit`: an undoable step once
// accepted; `how.field`: the input that made it (for the refusal message).
function propose(model, how) {
  const previous = pending;
  pending = {
    model: model || state.model,
    commit: !!(how && how.commit) || !!(previous && previous.commit),
    preview: !!(how && how.preview) && !(previous && previous.commit),
    message: (how && how.message) || (previous && previous.message) || '',
    t0: performance.now(),
    onRefused: how && how.onRefused,
    field: (how && how.field) || (previous && previous.field) || null,
  };
  kick();
}

function kick() {
  if (serverBusy || !pending) return;
  const job = pending;
  pending = null;
  serverBusy = true;
  outstanding += 1;
  applied = applied
    .then(() => send(job))
    .then(apply)
    .then(() => {
      serverBusy = false;
      kick();
    });
}

function unreachable(e) {
  return { ok: false, status: 0, value: { error: { message: `the studio server cannot be reached (${e.message})` } } };
}

// Sends `job`; resolves to {job, result: {ok, status, value}, tSent, tAnswered}. Drag
// frames ask for display lists, painted on canvases when the answer is applied.
async function send(job) {
  const request = {
    model: JSON.stringify(job.model, null, 1),
    views: shownViews(),
    at: state.at,
  };
  if (job.preview) request.encoding = 'display-list';
  Object.assign(request, extra(job.preview ? { samples: PREVIEW_SAMPLES } : {}));
  const tSent = performance.now();
  const result = await postJson('/api/render', request).catch(unreachable);
  return { job, result, tSent, tAnswered: performance.now() };
}

function apply({ job, result, tSent, tAnswered }) {
  if (result.ok) {
    accept(result.value, job);
    // The layout the next paint needs, done now so that it is measured.
    void $('#views').offsetHeight;
    const tDone = performance.now();
    // latency: from the input event to the views painted and laid out anew; work: from
    // the request to the same point; fetch: from the request to the server's answer; dom:
    // from the answer to the end (painting, and the page's update); interval: since the
    // previous frame.
    const last = state.timings[state.timings.length - 1];
    const timing = {
      latency: tDone - job.t0,
      work: tDone - tSent,
      fetch: tAnswered - tSent,
      server: result.value.ms,
      dom: tDone - tAnswered,
      at: tDone,
      interval: last ? tDone - last.at : null,
      preview: job.preview,
      views: Object.keys(result.value.figures || result.value.drawings).length,
      shown: null,
    };
    state.timings.push(timing);
    // shown: from the input event to the end of the first frame drawn after it (the
    // callback of the next animation frame, then the task after that frame).
    requestAnimationFrame(() => setTimeout(() => { timing.shown = performance.now() - job.t0; }, 0));
  } else {
    const err = (result.value && result.value.error) || { message: 'refused' };
    clearFieldErrors();
    showFieldError(err.field, err.message, err.detail, job.field);
    alertMessage(err.message);
    if (job.onRefused) job.onRefused();
    fillModelFields();
  }
  outstanding -= 1;
  if (!outstanding && !pending) {
    const waiters = idleWaiters;
    idleWaiters = [];
    waiters.forEach((w) => w());
  }
}

function accept(value, job) {
  state.model = value.model;
  state.info = value.info;
  state.family = value.family;
  state.pointDegrees = value.pointDegrees;
  state.renders += 1;
  const text = JSON.stringify(state.model);
  if (job.commit && text !== state.committed) {
    if (state.committed !== null) state.history.push(state.committed);
    state.future = [];
    state.committed = text;
  }
  if (state.selected >= state.model.control_points.length) state.selected = state.model.control_points.length - 1;
  state.refused = value.refused || {};
  syncViewControls();
  drawFigures(value);
  if (job.preview) {
    schedulePanel(value.table);
  } else {
    updatePanelNow(value.table);
  }
  // A refused view's reason is its box's title, not an alert.
  const errors = Object.entries(value.errors).filter(([v]) => !(v in state.refused));
  if (job.message) status(job.message);
  else if (errors.length) alertMessage(errors.map(([v, e]) => `${v}: ${e}`).join('\n'));
  else if ($('#alert').textContent) $('#alert').textContent = '';
}

// The pixel size of a view's canvas: its box (the canvas may be hidden) times the device's
// pixel ratio.
function canvasSize(host) {
  const ratio = window.devicePixelRatio || 1;
  return [Math.max(1, Math.round(host.clientWidth * ratio)), Math.max(1, Math.round(host.clientHeight * ratio))];
}

export { post, postJson, extra, pending, outstanding, idleWaiters, shownViews, propose, canvasSize };
