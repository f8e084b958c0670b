// The studio page. It holds the model as the JSON object a `.json` save writes, edits that
// object, and asks the server (POST /api/render) to validate it, evaluate it and draw the views
// shown. No geometry is computed here: every curve, figure and refusal comes from the server.
// A settled figure is the SVG `neutrospline plot` writes; while a point is dragged or a view
// turned, the server sends the same drawings as display lists, which are painted on canvases
// (six SVG documents take tens of milliseconds to lay out, six canvases a few).
//
// The entry module: it starts the page and sets `window.studio` (what the browser tests read).
// The page's modules are under modules/ (state and undo, the request queue, the figures and
// dragging, the side panel, files, fitting): plain ES modules, no bundler.

import { attachDragging, buildPanels, syncViewControls } from './modules/figures.js';
import { attachFiles } from './modules/files.js';
import { attachFields, attachKeys, attachViews, fillFamilies } from './modules/panel.js';
import { idleWaiters, outstanding, pending, propose } from './modules/queue.js';
import { $, alertMessage, clone, redo, state, undo } from './modules/state.js';

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
  fillFamilies(r.families);
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
