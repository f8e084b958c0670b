// The studio page, fitting.js. Fitting: the data CSV shown over the curve, and `neutrospline fit`
// run on it (POST /api/fit with the CLI's option names).

import { syncViewControls } from './figures.js';
import { postJson, propose } from './queue.js';
import { $, alertMessage, state } from './state.js';

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

// The numbers of a text such as "8,6" (a degree or control-point pair), for an option that
// takes one or two whole numbers.
function numbers(text) {
  return text.split(',').map((t) => t.trim()).filter((t) => t).map(Number);
}

async function fitData() {
  if (!state.data) { alertMessage('load a data CSV first'); return; }
  const surface = $('#fit-surface').checked;
  const target = $('#fit-target').value;
  const value = $('#fit-value').value.trim();
  const options = {
    degree: surface ? [Number($('#fit-degree').value)] : Number($('#fit-degree').value),
    parametrization: $('#fit-parametrization').value,
    weights: $('#fit-weights').value,
    smoothing: Number($('#fit-smoothing').value),
  };
  if (surface) {
    const grid = $('#fit-grid').value.trim();
    if (grid) options.grid = grid;
  } else {
    options.kind = $('#fit-kind').value;
    options.closed = $('#fit-closed').checked;
  }
  if (target === 'interpolate') options.interpolate = true;
  else if (target === 'control-points' && value) {
    options['control-points'] = surface ? numbers(value) : Number(value);
  } else if (target === 'tolerance' && value) options.tolerance = Number(value);
  // Every fit option, the membership rule among them, goes in `options` (FitRequest's names,
  // or SurfaceFitRequest's for a surface).
  options.membership = (state.model && state.model.membership) || 'neutrosophic';
  const r = await postJson('/api/fit', { data: state.data, options, surface });
  if (!r.ok) { alertMessage(r.value.error.message); return; }
  const rep = r.value.report;
  const size = surface
    ? `control points ${rep.control_points.join(' x ')} (degrees ${rep.degrees.join(', ')})`
    : `control points ${rep.control_points} (degree ${rep.degree})`;
  const at = surface ? ` (u = ${rep.worst_parameters[0].toPrecision(6)}, v = ${rep.worst_parameters[1].toPrecision(6)})` : '';
  const worst = `worst point ${rep.worst_index}${at}: position residual ${rep.worst_distance}`;
  $('#fit-report').textContent = [
    size,
    rep.tolerance !== null ? `tolerance ${rep.tolerance}, ${rep.tolerance_met ? 'met' : 'NOT met'}` : '',
    worst,
    'channel  max error  rms error',
    ...Object.keys(rep.max_error).map((c) => `  ${c}  ${rep.max_error[c].toPrecision(4)}  ${rep.rms_error[c].toPrecision(4)}`),
    rep.warning ? `warning: ${rep.warning}` : '',
  ].filter((s) => s).join('\n');
  state.selected = 0;
  state.shown.data = true;
  syncViewControls();
  const fitted = surface ? rep.control_points.join(' x ') : rep.control_points;
  propose(r.value.model, { commit: true, message: `fitted ${fitted} control points to ${state.data.name}` });
}

export { loadData, fitData };
