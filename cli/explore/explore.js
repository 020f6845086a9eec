// explore.js: the explorer page written by `qm-atms explore` (docs/EXPLORER.md). It reads the data
// blob of the page (schema qm-explore/1) and shows one kinematic pair at a time: its configuration
// space with its places (a picture drawn by qm-atms whose elements carry data-place="ID") and its
// two parts drawn at a place's sample configuration (qm-atms gives each place's transforms and
// contact marks; the page only swaps them). No network, no library.
'use strict';

const data = JSON.parse(document.getElementById('qm-data').textContent);
const byId = (id) => document.getElementById(id);
const sign = (s) => (s > 0 ? '+' : s < 0 ? '-' : '0');
const direction = (d) => '(' + sign(d[0]) + ' ' + sign(d[1]) + ')';
const escape = (s) => String(s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);

let pair = null;      // the pair shown
let selected = null;  // the place kept by a click or the list, or null for the parts as drawn

function value(k, v) {
  const unit = pair.units[k];
  if (unit === 'fixed') return pair.parts[k] + ' fixed';
  return pair.parts[k] + ' = ' + (unit === 'degrees' ? v.toFixed(2) + '\u00b0' : v.toPrecision(4));
}

function kindText(place) {
  let text = place.kind;
  if (place.kind === 'join') {
    text += ' (' + place.join_kind + (place.concave === undefined ? '' : place.concave ? ', concave' : ', convex') + ')';
  }
  if (place.axis !== undefined) text += ' along ' + pair.parts[place.axis];
  if (place.gap) text += ' (a gap, 8.1.6)';
  return text;
}

// The next places under each motion (s0 of the first part, s1 of the second), 8.1.3.
function adjacencyTable(id) {
  const rows = [1, 0, -1].map((s0) => {
    const cells = [1, 0, -1].map((s1) => {
      if (s0 === 0 && s1 === 0) return '<td>at rest</td>';
      const next = pair.vocabulary.adjacency.filter((a) => a.from === id && a.motion[0] === s0 && a.motion[1] === s1);
      const items = next.map((a) => (a.constrained
        ? '<span class="constrained">blocked</span>'
        : '<button data-goto="' + a.to + '" title="' + (a.instantaneous ? 'instantaneous' : 'over an interval') + '">' +
          (a.instantaneous ? '&rarr; ' : '&#8658; ') + a.to + '</button>'));
      return '<td>' + (items.join(' ') || '&ndash;') + '</td>';
    });
    return '<tr><th>' + sign(s0) + '</th>' + cells.join('') + '</tr>';
  });
  return '<table class="adjacency"><caption>next place under each motion (&rarr; instantaneous, &#8658; over an interval)</caption>' +
    '<tr><th>' + escape(pair.parts[0]) + ' \\ ' + escape(pair.parts[1]) + '</th><th>+</th><th>0</th><th>-</th></tr>' + rows.join('') + '</table>';
}

function describe(id) {
  if (id === null) return '<p>The parts as drawn. Point at a place, or pick one.</p>';
  const place = pair.vocabulary.places[id];
  const sample = pair.samples[id];
  const normals = place.normals.map(direction).join(', ') || 'none';
  return '<p><b>Place ' + id + '</b>: ' + escape(kindText(place)) + '; normals ' + normals +
    (place.label ? '; ' + escape(place.label) : '') + '.</p><p>Sample configuration: ' +
    escape(value(0, sample.config[0]) + ', ' + value(1, sample.config[1])) + '; ' + sample.contacts + ' contact' +
    (sample.contacts === 1 ? '' : 's') + (sample.overlap ? ' (the parts overlap here)' : '') + '.</p>' + adjacencyTable(id);
}

function showPlace(id) {
  for (const e of byId('cspace').querySelectorAll('.selected')) e.classList.remove('selected');
  if (id !== null) for (const e of byId('cspace').querySelectorAll('[data-place="' + id + '"]')) e.classList.add('selected');
  const at = id === null ? pair.as_drawn : pair.samples[id];
  pair.parts.forEach((name, k) => {
    const g = byId('drawing').querySelector('g.part[data-part="' + CSS.escape(name) + '"]');
    if (g) g.setAttribute('transform', at.transforms[k]);
  });
  byId('drawing').querySelector('g.contacts').innerHTML = at.contacts_svg;
  byId('drawing-caption').textContent = (id === null ? 'The parts as drawn' : 'The parts at place ' + id) + ': ' +
    value(0, at.config[0]) + ', ' + value(1, at.config[1]);
  byId('place-info').innerHTML = describe(id);
  byId('place-select').value = id === null ? '' : String(id);
}

function select(id) {
  selected = id;
  showPlace(id);
}

function showPair(index) {
  pair = data.pairs[index];
  byId('pairs').querySelectorAll('button').forEach((b, k) => b.setAttribute('aria-pressed', String(k === index)));
  byId('cspace').innerHTML = pair.cspace_svg;
  byId('drawing').innerHTML = pair.drawing_svg;
  byId('place-select').innerHTML = '<option value="">as drawn</option>' + pair.vocabulary.places.map((p) =>
    '<option value="' + p.id + '">' + p.id + ': ' + escape(kindText(p)) + ' ' + p.normals.map(direction).join(' ') + '</option>').join('');
  select(null);
}

function placeOf(event) {
  const e = event.target.closest('[data-place]');
  return e ? Number(e.getAttribute('data-place')) : null;
}

function start() {
  byId('title').textContent = 'qm-atms explorer: ' + data.mechanism;
  document.title = byId('title').textContent;
  byId('pairs').innerHTML = data.pairs.map((p, k) => '<button data-pair="' + k + '">' + escape(p.parts.join(' \u2013 ')) + '</button>').join('');
  byId('pairs').addEventListener('click', (e) => {
    const b = e.target.closest('button[data-pair]');
    if (b) showPair(Number(b.getAttribute('data-pair')));
  });
  const cspace = byId('cspace');
  cspace.addEventListener('click', (e) => { const id = placeOf(e); if (id !== null) select(id); });
  cspace.addEventListener('mouseover', (e) => { const id = placeOf(e); if (id !== null) showPlace(id); });
  cspace.addEventListener('mouseout', (e) => { if (placeOf(e) !== null) showPlace(selected); });
  byId('place-select').addEventListener('change', (e) => select(e.target.value === '' ? null : Number(e.target.value)));
  byId('place-info').addEventListener('click', (e) => {
    const b = e.target.closest('button[data-goto]');
    if (b) select(Number(b.getAttribute('data-goto')));
  });
  if (data.pairs.length > 0) showPair(0);
  else byId('place-info').textContent = 'This mechanism has no kinematic pair with a configuration space.';
}

start();
