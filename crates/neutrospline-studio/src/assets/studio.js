// The studio page. It holds the model as the JSON object a `.json` save writes, edits that
// object, and asks the server (POST /api/render) to validate it, evaluate it and draw the views
// shown. No geometry is computed here: every curve, figure and refusal comes from the server.
// A settled figure is the SVG `neutrospline plot` writes; while a point is dragged or a view
// turned, the server sends the same drawings as display lists, which are painted on canvases
// (six SVG documents take tens of milliseconds to lay out, six canvases a few).
'use strict';

(function () {
  const PAPER_VIEWS = ['plane', 'controls', 'truth', 'indeterminacy', 'falsity', 'all'];
  const OTHER_VIEWS = ['score', 'data'];
  const TURNABLE = ['truth', 'indeterminacy', 'falsity', 'all', 'score'];
  const DEGREES = ['truth', 'indeterminacy', 'falsity'];
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
    layout: 'grid',
    large: 'plane',
    camera: clone(DEFAULT_CAMERA),
    at: '',
    data: null,           // {name, text}
    colorBy: 'truth',
    info: null,
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

  // The field of a refusal (`control_points[1].truth`, `knots`, ...) -> the input next to which
  // the message is shown.
  function showFieldError(field, message, detail) {
    if (!field) return;
    const m = /^control_points\[(\d+)\]\.(\w+)/.exec(field);
    let key = field.split(/[.[]/)[0];
    const p = /^control_points\[(\d+)\]/.exec(field);
    if (p) {
      const index = Number(p[1]);
      if (index !== state.selected) selectPoint(index, false);
      // The reader names the point (`control_points[1]`) and the message the value
      // (`truth = 1.2 is outside ...`), or the field names both.
      const named = /^(\w+) = /.exec(detail || '');
      key = m ? m[2] : named ? named[1] : 'position';
      const input = document.querySelector(`#point-fields input[name=${key}]`);
      if (input) input.classList.add('invalid');
      if (!DEGREES.includes(key)) key = 'position';
    }
    const slot = document.querySelector(`[data-error-for="${key}"]`);
    if (slot) slot.textContent = message;
  }

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

  function extra() {
    return {
      azimuth: state.camera.azimuth,
      elevation: state.camera.elevation,
      data: state.data,
      colorBy: state.colorBy,
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
    return PAPER_VIEWS.concat(OTHER_VIEWS).filter((v) => state.shown[v]);
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
    if (job.preview) {
      request.samples = PREVIEW_SAMPLES;
      request.encoding = 'display-list';
    }
    Object.assign(request, extra());
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
      showFieldError(err.field, err.message, err.detail);
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

  function accept(value, job) {
    state.model = value.model;
    state.info = value.info;
    state.renders += 1;
    const text = JSON.stringify(state.model);
    if (job.commit && text !== state.committed) {
      if (state.committed !== null) state.history.push(state.committed);
      state.future = [];
      state.committed = text;
    }
    if (state.selected >= state.model.control_points.length) state.selected = state.model.control_points.length - 1;
    drawFigures(value);
    if (job.preview) {
      schedulePanel(value.table);
    } else {
      clearTimeout(panelTimer);
      panelTimer = null;
      updatePanel(value.table);
    }
    if (job.message) status(job.message);
    else if (Object.keys(value.errors).length) alertMessage(Object.entries(value.errors).map(([v, e]) => `${v}: ${e}`).join('\n'));
    else if ($('#alert').textContent) $('#alert').textContent = '';
  }

  // The pixel size of a view's canvas: its box (the canvas may be hidden) times the device's
  // pixel ratio.
  function canvasSize(host) {
    const ratio = window.devicePixelRatio || 1;
    return [Math.max(1, Math.round(host.clientWidth * ratio)), Math.max(1, Math.round(host.clientHeight * ratio))];
  }

  // ------------------------------------------------------------------------------------------
  // Figures

  const panels = {};

  function buildPanels() {
    const host = $('#views');
    for (const view of PAPER_VIEWS.concat(OTHER_VIEWS)) {
      const figure = document.createElement('figure');
      figure.className = 'panel';
      figure.dataset.view = view;
      // The host stacks the figure (an SVG document), the canvas that shows drag frames over
      // it, and in the plane view the control-point handles over both.
      figure.innerHTML = `<figcaption><span>${view}</span><button class="enlarge" title="Show this view large">⤢</button></figcaption>`
        + '<div class="host"><div class="figure"></div><canvas class="preview" hidden></canvas></div>';
      if (view === 'plane') {
        const overlay = document.createElementNS(SVG_NS, 'svg');
        overlay.setAttribute('class', 'studio-overlay');
        overlay.setAttribute('viewBox', '0 0 1600 1200');
        figure.querySelector('.host').appendChild(overlay);
      }
      figure.querySelector('.enlarge').addEventListener('click', () => {
        if (state.layout === 'large' && state.large === view) { state.layout = 'grid'; }
        else { state.layout = 'large'; state.large = view; }
        syncViewControls();
        propose(null);
      });
      host.appendChild(figure);
      panels[view] = figure;
      attachTurning(figure, view);
    }
  }

  function syncViewControls() {
    $('#layout').value = state.layout;
    $('#large-view').value = state.large;
    $('#views').classList.toggle('large', state.layout === 'large');
    const shown = shownViews();
    for (const [view, panel] of Object.entries(panels)) {
      panel.hidden = !shown.includes(view);
      panel.classList.toggle('turnable', isTurnable(view));
    }
    document.querySelectorAll('#view-toggles input').forEach((box) => { box.checked = state.shown[box.value]; });
  }

  function isTurnable(view) {
    if (!state.info) return TURNABLE.includes(view);
    if (state.info.surface) return view !== 'plane';
    return TURNABLE.includes(view) || (state.info.dimension === 3 && view !== 'data');
  }

  function drawFigures(value) {
    const shown = shownViews();
    const figures = value.figures || {};
    const drawings = value.drawings || {};
    for (const [view, panel] of Object.entries(panels)) {
      put(panel, 'hidden', !shown.includes(view));
      panel.classList.toggle('turnable', isTurnable(view));
      if (!shown.includes(view)) continue;
      const host = panel.querySelector('.host');
      const figure = host.querySelector('.figure');
      const canvas = host.querySelector('canvas.preview');
      if (view in drawings) {
        const [width, height] = canvasSize(host);
        if (canvas.width !== width || canvas.height !== height) {
          canvas.width = width;
          canvas.height = height;
        }
        self.paintDisplayList(canvas, drawings[view]);
        put(canvas, 'hidden', false);
        // The figure under the canvas is not drawn (else every frame would draw it too).
        put(figure, 'hidden', true);
        continue;
      }
      put(canvas, 'hidden', true);
      put(figure, 'hidden', false);
      if (view in figures) {
        figure.innerHTML = figures[view];
      } else if (view in value.errors) {
        figure.innerHTML = '';
        const p = document.createElement('p');
        p.className = 'view-error';
        p.textContent = value.errors[view];
        figure.appendChild(p);
      }
    }
    state.handles = value.handles;
    const size = drawings.plane ? [drawings.plane.width, drawings.plane.height] : figureSize(panels.plane);
    placeHandles(value.handles, size, !!(figures.plane || drawings.plane));
  }

  // The width and height of a panel's figure, from its SVG's view box.
  function figureSize(panel) {
    const svg = panel.querySelector('.figure svg');
    const box = svg && svg.viewBox && svg.viewBox.baseVal;
    return box && box.width ? [box.width, box.height] : null;
  }

  // The plane view's handles over a figure of `size` pixels: moved in place when their number
  // is unchanged (a drag), else made anew.
  function placeHandles(handles, size, shown) {
    const overlay = panels.plane.querySelector('.studio-overlay');
    const pixels = shown && handles ? handles.pixels : [];
    if (size) overlay.setAttribute('viewBox', `0 0 ${size[0]} ${size[1]}`);
    let circles = overlay.querySelectorAll('[data-point-index]');
    if (circles.length !== pixels.length) {
      overlay.textContent = '';
      pixels.forEach((_, k) => {
        const c = document.createElementNS(SVG_NS, 'circle');
        c.setAttribute('r', 16);
        c.setAttribute('data-point-index', String(k));
        c.setAttribute('tabindex', '0');
        overlay.appendChild(c);
      });
      circles = overlay.querySelectorAll('[data-point-index]');
    }
    pixels.forEach(([x, y], k) => {
      circles[k].setAttribute('cx', x);
      circles[k].setAttribute('cy', y);
      circles[k].setAttribute('class', 'studio-handle' + (k === state.selected ? ' selected' : ''));
    });
  }

  // Pointer position in the SVG's own pixels (the figure's coordinates).
  function svgPoint(svg, event) {
    const pt = svg.createSVGPoint();
    pt.x = event.clientX;
    pt.y = event.clientY;
    return pt.matrixTransform(svg.getScreenCTM().inverse());
  }

  let drag = null;

  // Keeps the pointer's moves coming to `host` when it leaves it (not for synthetic events).
  function capture(host, pointerId) {
    try { host.setPointerCapture(pointerId); } catch (e) { /* not an active pointer */ }
  }

  function attachDragging() {
    const host = panels.plane.querySelector('.host');
    host.addEventListener('pointerdown', (event) => {
      const handle = event.target.closest('[data-point-index]');
      if (!handle) return;
      const k = Number(handle.getAttribute('data-point-index'));
      selectPoint(k, true);
      // How a move of the pointer moves the point (from the server: the inverse of the plane
      // view's map for a plane curve; for a space curve, the least move under the pointer).
      const map = state.handles && state.handles.drag;
      const svg = host.querySelector('.studio-overlay');
      if (!map || !svg) {
        status(`point ${k} selected (this view cannot place it under the pointer: edit its fields to move it)`);
        return;
      }
      event.preventDefault();
      // The fields follow the drag; one being edited would keep its text.
      if (document.activeElement instanceof HTMLElement) document.activeElement.blur();
      capture(host, event.pointerId);
      const p = svgPoint(svg, event);
      const point = state.model.control_points[k];
      const axes = COORDINATES.slice(0, map.length);
      drag = { k, map, axes, start: p, from: axes.map((a) => point[a]), moved: false, pointerId: event.pointerId };
    });
    host.addEventListener('pointermove', (event) => {
      if (!drag || event.pointerId !== drag.pointerId) return;
      const svg = host.querySelector('.studio-overlay');
      const p = svgPoint(svg, event);
      const [dx, dy] = [p.x - drag.start.x, p.y - drag.start.y];
      const m = clone(state.model);
      drag.axes.forEach((a, i) => {
        m.control_points[drag.k][a] = drag.from[i] + drag.map[i][0] * dx + drag.map[i][1] * dy;
      });
      drag.moved = true;
      drag.last = m.control_points[drag.k];
      propose(m, { preview: true });
    });
    const end = (event) => {
      if (!drag || event.pointerId !== drag.pointerId) return;
      const d = drag;
      drag = null;
      if (!d.moved) return;
      const m = clone(state.model);
      d.axes.forEach((a) => { m.control_points[d.k][a] = d.last[a]; });
      const at = d.axes.map((a) => fmt(d.last[a])).join(', ');
      propose(m, { commit: true, message: `moved point ${d.k} to (${at})` });
    };
    host.addEventListener('pointerup', end);
    host.addEventListener('pointercancel', end);
  }

  function attachTurning(figure, view) {
    const host = figure.querySelector('.host');
    let turn = null;
    host.addEventListener('pointerdown', (event) => {
      if (!isTurnable(view) || event.target.closest('[data-point-index]')) return;
      event.preventDefault();
      capture(host, event.pointerId);
      turn = { x: event.clientX, y: event.clientY, camera: clone(state.camera), id: event.pointerId };
    });
    host.addEventListener('pointermove', (event) => {
      if (!turn || event.pointerId !== turn.id) return;
      const scale = 360 / Math.max(200, host.clientWidth);
      state.camera.azimuth = wrap(turn.camera.azimuth - (event.clientX - turn.x) * scale);
      state.camera.elevation = Math.max(-90, Math.min(90, turn.camera.elevation + (event.clientY - turn.y) * scale));
      propose(null, { coalesce: true, preview: true });
    });
    const end = () => {
      if (turn) status(`camera: azimuth ${fmt(state.camera.azimuth)}°, elevation ${fmt(state.camera.elevation)}°`);
      turn = null;
    };
    host.addEventListener('pointerup', end);
    host.addEventListener('pointercancel', end);
  }

  function wrap(a) {
    let r = ((a + 180) % 360 + 360) % 360 - 180;
    return Math.round(r * 10) / 10;
  }

  function fmt(v) {
    return String(Math.round(v * 1e6) / 1e6);
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
    const head = t.createTHead().insertRow();
    for (const c of table.columns) {
      const th = document.createElement('th');
      th.textContent = c;
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
    const rule = m.membership || 'neutrosophic';
    for (const d of DEGREES) {
      const input = fields.querySelector(`input[name=${d}]`);
      const slider = fields.querySelector(`input[data-slider=${d}]`);
      let value = p[d];
      let derived = false;
      if (rule === 'intuitionistic' && d === 'indeterminacy') {
        value = p.indeterminacy !== undefined ? p.indeterminacy : hesitation(p);
        derived = true;
      }
      if (rule === 'fuzzy' && d !== 'truth') { value = 0; derived = true; }
      put(input, 'disabled', derived);
      put(slider, 'disabled', derived);
      setValue(input, value, force);
      if (document.activeElement !== slider) put(slider, 'value', String(value === undefined ? 0 : value));
    }
    put($('#rule-note'), 'textContent', {
      neutrosophic: 'neutrosophic: truth, indeterminacy and falsity each in [0, 1], independent',
      intuitionistic: 'intuitionistic: truth + falsity <= 1; indeterminacy = 1 - truth - falsity',
      fuzzy: 'fuzzy: truth only; indeterminacy and falsity are 0',
    }[rule]);
    const curve = !surface;
    put($('#add-point'), 'disabled', !curve);
    put($('#insert-point'), 'disabled', !curve);
    put($('#delete-point'), 'disabled', !curve || n <= 2);
  }

  // The hesitation 1 - T - F shown (not sent) under the intuitionistic rule.
  function hesitation(p) {
    const h = 1 - p.truth - (p.falsity || 0);
    return Math.max(0, Math.round(h * 1e12) / 1e12);
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
    });
  }

  function attachFields() {
    const fields = $('#point-fields');
    for (const key of ['x', 'y', 'z', 'weight'].concat(DEGREES)) {
      const input = fields.querySelector(`input[name=${key}]`);
      input.addEventListener('change', () => {
        input.classList.remove('invalid');
        editPoint(key, numberOrText(input.value), true);
      });
    }
    for (const d of DEGREES) {
      const slider = fields.querySelector(`input[data-slider=${d}]`);
      slider.addEventListener('input', () => editPoint(d, Number(slider.value), false));
      slider.addEventListener('change', () => editPoint(d, Number(slider.value), true));
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

  function setMembership(rule) {
    const m = clone(state.model);
    const from = m.membership || 'neutrosophic';
    for (const p of m.control_points) {
      if (rule === 'neutrosophic') {
        if (from === 'intuitionistic' && p.indeterminacy === undefined) p.indeterminacy = hesitation(p);
        if (from === 'fuzzy') { p.indeterminacy = p.indeterminacy || 0; p.falsity = p.falsity || 0; }
      } else if (rule === 'intuitionistic') {
        delete p.indeterminacy;
        if (p.falsity === undefined) p.falsity = 0;
      } else {
        delete p.indeterminacy;
        delete p.falsity;
      }
    }
    m.membership = rule;
    propose(m, { commit: true, message: `membership: ${rule}` });
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

  // ------------------------------------------------------------------------------------------
  // Files

  function download(blob, filename) {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(blob);
    a.download = filename;
    document.body.appendChild(a);
    a.click();
    setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
  }

  function stem() {
    if (state.file) return state.file.replace(/^.*[\\/]/, '').replace(/\.[^.]*$/, '');
    return 'model';
  }

  async function saveAs(format) {
    const r = await postJson('/api/convert', { model: JSON.stringify(state.model), format });
    if (!r.ok) { alertMessage(r.value.error.message); return; }
    download(new Blob([r.value.text], { type: 'text/plain' }), r.value.filename);
    status(`downloaded ${r.value.filename}`);
  }

  async function save() {
    const r = await postJson('/api/save', { model: JSON.stringify(state.model) });
    if (!r.ok) { alertMessage(r.value.error.message); return; }
    status(`saved ${r.value.saved}`);
  }

  async function exportFigure(format) {
    const view = $('#export-view').value;
    const response = await post('/api/export', Object.assign({ model: JSON.stringify(state.model), view, format }, extra()));
    if (!response.ok) {
      const v = await response.json().catch(() => ({ error: { message: response.statusText } }));
      alertMessage(v.error.message);
      return;
    }
    const blob = await response.blob();
    const filename = `${stem()}-${view}.${format}`;
    download(blob, filename);
    status(`exported ${filename}`);
  }

  async function openText(name, text) {
    const r = await postJson('/api/open', { name, text });
    if (!r.ok) { alertMessage(r.value.error.message); return; }
    state.selected = 0;
    $('#file-name').textContent = state.file
      ? `${state.file} (showing ${r.value.name}; Save writes ${state.file})`
      : `${r.value.name} (no file: save downloads)`;
    propose(r.value.model, { commit: true, message: `opened ${r.value.name}` });
  }

  async function loadData(name, text) {
    const membership = (state.model && state.model.membership) || 'neutrosophic';
    const r = await postJson('/api/data', { name, text, membership });
    if (!r.ok) { alertMessage(r.value.error.message); return; }
    state.data = { name, text };
    state.shown.data = true;
    $('#data-info').textContent = `${r.value.name}: ${r.value.points} points (${r.value.dimension}-D)`;
    syncViewControls();
    propose(null, { message: `data: ${r.value.points} points from ${r.value.name}` });
  }

  async function fitData() {
    if (!state.data) { alertMessage('load a data CSV first'); return; }
    const target = $('#fit-target').value;
    const value = $('#fit-value').value.trim();
    const options = {
      degree: Number($('#fit-degree').value),
      parametrization: $('#fit-parametrization').value,
      weights: $('#fit-weights').value,
      smoothing: Number($('#fit-smoothing').value),
      kind: $('#fit-kind').value,
      closed: $('#fit-closed').checked,
    };
    if (target === 'interpolate') options.interpolate = true;
    else if (target === 'control-points' && value) options['control-points'] = Number(value);
    else if (target === 'tolerance' && value) options.tolerance = Number(value);
    options.membership = (state.model && state.model.membership) || 'neutrosophic';
    const r = await postJson('/api/fit', { data: state.data, options });
    if (!r.ok) { alertMessage(r.value.error.message); return; }
    const rep = r.value.report;
    $('#fit-report').textContent = [
      `control points ${rep.control_points} (degree ${rep.degree})`,
      rep.tolerance !== null ? `tolerance ${rep.tolerance}, ${rep.tolerance_met ? 'met' : 'NOT met'}` : '',
      `worst point ${rep.worst_index}: position residual ${rep.worst_distance}`,
      'channel  max error  rms error',
      ...Object.keys(rep.max_error).map((c) => `  ${c}  ${rep.max_error[c].toPrecision(4)}  ${rep.rms_error[c].toPrecision(4)}`),
    ].filter((s) => s).join('\n');
    state.selected = 0;
    state.shown.data = true;
    syncViewControls();
    propose(r.value.model, { commit: true, message: `fitted ${rep.control_points} control points to ${state.data.name}` });
  }

  function readFile(file) {
    return new Promise((resolve, reject) => {
      const reader = new FileReader();
      reader.onload = () => resolve(String(reader.result));
      reader.onerror = () => reject(reader.error);
      reader.readAsText(file);
    });
  }

  function attachFiles() {
    $('#open-file').addEventListener('change', async (e) => {
      const file = e.target.files[0];
      if (file) await openText(file.name, await readFile(file));
      e.target.value = '';
    });
    $('#data-file').addEventListener('change', async (e) => {
      const file = e.target.files[0];
      if (file) await loadData(file.name, await readFile(file));
      e.target.value = '';
    });
    $('#save').addEventListener('click', save);
    $('#save-toml').addEventListener('click', () => saveAs('toml'));
    $('#save-json').addEventListener('click', () => saveAs('json'));
    $('#export-svg').addEventListener('click', () => exportFigure('svg'));
    $('#export-png').addEventListener('click', () => exportFigure('png'));
    $('#undo').addEventListener('click', undo);
    $('#redo').addEventListener('click', redo);
    // Drop: on the data zone a data CSV, anywhere else a model.
    document.addEventListener('dragover', (e) => { e.preventDefault(); document.body.classList.add('dragging'); });
    document.addEventListener('dragleave', (e) => { if (!e.relatedTarget) document.body.classList.remove('dragging'); });
    document.addEventListener('drop', async (e) => {
      e.preventDefault();
      document.body.classList.remove('dragging');
      const file = e.dataTransfer && e.dataTransfer.files[0];
      if (!file) return;
      const text = await readFile(file);
      if (e.target.closest && e.target.closest('#data-drop')) await loadData(file.name, text);
      else await openText(file.name, text);
    });
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

  // ------------------------------------------------------------------------------------------
  // Start

  async function start() {
    buildPanels();
    attachViews();
    attachFields();
    attachFiles();
    attachKeys();
    attachDragging();
    syncViewControls();
    let r;
    try {
      const response = await fetch('/api/state');
      r = await response.json();
    } catch (e) {
      alertMessage(`the studio server cannot be reached (${e.message})`);
      return;
    }
    state.file = r.file;
    state.canSave = r.canSave;
    $('#file-name').textContent = r.file ? r.file : 'Example 1 (no file: save downloads)';
    state.committed = JSON.stringify(r.model);
    state.model = r.model;
    propose(r.model, { message: r.file ? `opened ${r.file}` : 'opened Example 1' });
  }

  window.studio = {
    model: () => clone(state.model),
    timings: state.timings,
    renders: () => state.renders,
    camera: () => clone(state.camera),
    // The map from model x, y to the plane view's pixels: [sx, sy, ox, oy] (null for 3-D).
    frame: () => (state.handles && state.handles.frame ? state.handles.frame.slice() : null),
    // How a pointer move of (dx, dy) figure pixels in the plane view moves a control point:
    // one row [per dx, per dy] per coordinate x, y (, z); null when the view cannot say.
    dragMap: () => (state.handles && state.handles.drag ? clone(state.handles.drag) : null),
    idle: () => (outstanding || pending ? new Promise((r) => idleWaiters.push(r)) : Promise.resolve()),
    // Paints a display list on a canvas, as drag frames are painted (for tests).
    paintDisplayList: self.paintDisplayList,
    undo,
    redo,
  };

  start();
})();
