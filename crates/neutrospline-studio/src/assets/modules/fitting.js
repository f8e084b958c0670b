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
  // Every fit option, the membership rule among them, goes in `options` (FitRequest's names).
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

export { loadData, fitData };
