// The studio page, files.js. Files: open, save, save as TOML or JSON, and figure exports
// (downloads).

import { loadData } from './fitting.js';
import { extra, post, postJson, propose } from './queue.js';
import { $, alertMessage, redo, state, status, undo } from './state.js';

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
  const response = await post('/api/export', Object.assign({ model: JSON.stringify(state.model), format }, extra({ view })));
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

export { attachFiles };
