// The studio page, figures.js. The figures: the view panels, SVG or canvas drawings, the plane
// view's handles and dragging them, and turning the 3-D views.

import { put, selectPoint } from './panel.js';
import { canvasSize, propose, shownViews } from './queue.js';
import { $, COORDINATES, OTHER_VIEWS, PAPER_VIEWS, SVG_NS, TURNABLE, clone, state, status } from './state.js';

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
  // A view the model's family cannot draw: its box unticked and disabled, the plot crate's
  // reason as its title (ticked again when a family that draws it comes back).
  const refused = state.refused || {};
  document.querySelectorAll('#view-toggles input').forEach((box) => {
    const reason = refused[box.value];
    box.disabled = !!reason;
    box.checked = state.shown[box.value] && !reason;
    box.parentElement.title = reason || '';
    box.parentElement.classList.toggle('refused', !!reason);
  });
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

export { buildPanels, syncViewControls, drawFigures, attachDragging, fmt };
