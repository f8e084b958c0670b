// Paints a display list on a canvas: neutrospline-plot's `Drawing::to_display_list`, whose
// format is in docs/architecture.md. The drawing's primitives are painted in order, the figure
// scaled to fit the canvas's pixels (its `width` x `height`, set by the caller) as the SVG is
// scaled to fit its box, and centred. The page paints its drag frames with it
// (studio.js), and tests paint with it.
'use strict';

function paintDisplayList(canvas, list) {
  const pw = canvas.width;
  const ph = canvas.height;
  // Opaque: the page's white shows in the margins, as around the SVG.
  const g = canvas.getContext('2d', { alpha: false });
  g.setTransform(1, 0, 0, 1, 0, 0);
  g.fillStyle = '#ffffff';
  g.fillRect(0, 0, pw, ph);
  const scale = Math.min(pw / list.width, ph / list.height);
  g.setTransform(scale, 0, 0, scale, (pw - scale * list.width) / 2, (ph - scale * list.height) / 2);
  g.fillStyle = '#ffffff';
  g.fillRect(0, 0, list.width, list.height);
  g.miterLimit = 4;  // SVG's default (the canvas's is 10)
  g.textBaseline = 'alphabetic';
  let lastFont = '';
  const styles = list.styles;
  const texts = list.texts;
  const gradients = {};
  const groups = [];  // per open group: the mesh width to restore, or null
  let meshWidth = 1;
  const path = (q, close) => {
    g.beginPath();
    g.moveTo(q[0], q[1]);
    for (let i = 2; i < q.length; i += 2) g.lineTo(q[i], q[i + 1]);
    if (close) g.closePath();
  };
  // Consecutive opaque unfilled lines and polylines of one style are stroked as one path
  // (what a curve drawn in depth-sorted pieces becomes): the same pixels, one stroke.
  let batch = -1;
  const flush = () => {
    if (batch >= 0) {
      const st = styles[batch];
      batch = -1;
      stroke(st.stroke, st.width, st.round ? 'round' : 'butt', st.round ? 'round' : 'miter', st.dash);
    }
  };
  const batchable = (k) => {
    const st = styles[k];
    return !st.fill && st.stroke && st.width > 0 && st.strokeOpacity === 1;
  };
  const addToBatch = (k, q) => {
    if (batch !== k) {
      flush();
      g.beginPath();
      batch = k;
    }
    g.moveTo(q[0], q[1]);
    for (let i = 2; i < q.length; i += 2) g.lineTo(q[i], q[i + 1]);
  };
  const stroke = (color, width, cap, join, dash) => {
    g.strokeStyle = color;
    g.lineWidth = width;
    g.lineCap = cap;
    g.lineJoin = join;
    g.setLineDash(dash || []);
    g.stroke();
  };
  const paint = (st) => {
    if (st.fill) {
      g.globalAlpha = st.fillOpacity;
      g.fillStyle = st.fill;
      g.fill();
    }
    if (st.stroke && st.width > 0) {
      g.globalAlpha = st.strokeOpacity;
      stroke(st.stroke, st.width, st.round ? 'round' : 'butt', st.round ? 'round' : 'miter', st.dash);
    }
    g.globalAlpha = 1;
  };
  for (const op of list.ops) {
    if (op[0] === 'p' && batchable(op[2])) { addToBatch(op[2], op[1]); continue; }
    if (op[0] === 'l' && batchable(op[5]) && (op[1] !== op[3] || op[2] !== op[4])) {
      addToBatch(op[5], [op[1], op[2], op[3], op[4]]);
      continue;
    }
    flush();
    switch (op[0]) {
      case 'g': groups.push(null); break;
      case 'm': groups.push(meshWidth); meshWidth = op[1]; break;
      case 'c':
        groups.push('clip');
        g.save();
        g.beginPath();
        g.rect(op[1], op[2], op[3], op[4]);
        g.clip();
        break;
      case 'e': {
        const top = groups.pop();
        if (top === 'clip') g.restore();
        else if (typeof top === 'number') meshWidth = top;
        break;
      }
      case 'r': g.beginPath(); g.rect(op[1], op[2], op[3], op[4]); paint(styles[op[5]]); break;
      case 'l': {
        const st = styles[op[5]];
        if (op[1] === op[3] && op[2] === op[4]) {
          // A zero-length line shows its round cap as a dot, as in SVG.
          if (st.stroke && st.round) {
            g.beginPath();
            g.arc(op[1], op[2], st.width / 2, 0, 2 * Math.PI);
            g.fillStyle = st.stroke;
            g.globalAlpha = st.strokeOpacity;
            g.fill();
            g.globalAlpha = 1;
          }
          break;
        }
        path([op[1], op[2], op[3], op[4]], false);
        paint(st);
        break;
      }
      case 'p': path(op[1], false); paint(styles[op[2]]); break;
      case 'P': path(op[1], true); paint(styles[op[2]]); break;
      case 'o': g.beginPath(); g.arc(op[1], op[2], op[3], 0, 2 * Math.PI); paint(styles[op[4]]); break;
      case 't': {
        const t = texts[op[4]];
        const font = `${t.bold ? 'bold ' : ''}${t.size}px ${list.font}`;
        if (font !== lastFont) {
          g.font = font;
          lastFont = font;
        }
        g.textAlign = t.anchor === 'middle' ? 'center' : t.anchor;
        g.save();
        g.translate(op[1], op[2]);
        if (t.rotate) g.rotate(t.rotate * Math.PI / 180);
        if (t.halo > 0) {
          g.strokeStyle = '#ffffff';
          g.lineWidth = t.halo;
          g.lineJoin = 'round';
          g.setLineDash([]);
          g.strokeText(op[3], 0, 0);
        }
        g.fillStyle = t.color;
        g.fillText(op[3], 0, 0);
        g.restore();
        break;
      }
      case 'f':
        path(op[1], true);
        g.fillStyle = op[2];
        g.fill();
        stroke(op[2], meshWidth, 'butt', 'round', null);
        break;
      case 'k':
        path([op[1], op[2], op[3], op[4]], false);
        stroke(op[5], meshWidth, 'butt', 'round', null);
        break;
      case 'G': gradients[op[1]] = op[2]; break;
      case 'R': {
        const [x, y, w, h] = op.slice(2);
        const stops = gradients[op[1]] || [];
        const gradient = g.createLinearGradient(0, y + h, 0, y);
        stops.forEach((c, i) => gradient.addColorStop(stops.length > 1 ? i / (stops.length - 1) : 0, c));
        g.fillStyle = gradient;
        g.fillRect(x, y, w, h);
        break;
      }
      default: break;
    }
  }
  flush();
}

self.paintDisplayList = paintDisplayList;
