// envision.js: the explorer page's envisionment views (docs/EXPLORER.md), after explore.js (whose
// `data`, `byId` and `escape` it uses). The data's "envisionment" is the envisioner's own JSON
// (qm-envisionment/1, as `qm-atms envision --json` writes it); "chains" has, per chain, a drawing of
// its parts, their motions' arrows and each pair's contact marks at each place; "paths" the
// described behaviours asked for with `explore --path`.
//   - a graph of a chain's states grouped by behavioural cycle (a ring each, in the order of its
//     transitions; a grid past 40 states), transient cycles (they cannot repeat), terminal states
//     (possible rests among them) and the other states (grids), at most VIEW_CAP states at a time (larger chains are shown by group,
//     in pages, or around a state);
//   - a state: the chain drawn at it (each pair's parts at its place's sample configuration, as
//     `draw --history` draws it) with its motions as arrows, the point in a pair's configuration
//     space, its next and previous states;
//   - a history (state ids; `...` between two finds the shortest path) played state by state.
'use strict';

const VIEW_CAP = 150;   // states drawn at once: more is not readable, and lays out slowly
const env = data.envisionment;
const graph = { chain: null, view: null, state: null, views: [] };
const play = { states: [], at: -1, timer: null };

const stateName = (c, s) => s.places.map((p) => p.parts.join('/') + '-' + p.place).join(' ') + ' ' +
  c.e.objects.map((o) => s.motions[o].slice(1, -1)).join(' ');
const idText = (c, id) => '#' + id + ' ' + stateName(c, c.byId.get(id));
const push = (map, key, value) => { if (!map.has(key)) map.set(key, []); map.get(key).push(value); };

function prepareChain(k) {
  const e = env.chains[k], c = { k, e, d: data.chains[k], byId: new Map(), next: new Map(), prev: new Map(), group: new Map() };
  for (const s of e.states) c.byId.set(s.id, s);
  for (const t of e.transitions) { push(c.next, t.from, t); push(c.prev, t.to, t); }
  const transient = e.transient_cycles || [], rests = new Set(e.possible_rests || []);
  c.rests = rests;
  c.transient = transient;
  e.cycles.forEach((ids, i) => ids.forEach((id) => c.group.set(id, i)));
  transient.forEach((t, i) => t.states.forEach((id) => c.group.set(id, 'transient-' + i)));
  const jams = e.terminal.filter((id) => !rests.has(id));
  for (const id of jams) c.group.set(id, 'terminal');
  const others = e.states.map((s) => s.id).filter((id) => !c.group.has(id));
  const paged = (label, ids) => {
    for (let from = 0; from < ids.length; from += VIEW_CAP) {
      const page = ids.length > VIEW_CAP ? ' ' + (from / VIEW_CAP + 1) + '/' + Math.ceil(ids.length / VIEW_CAP) : '';
      c.views.push({ label: label + page, ids: ids.slice(from, from + VIEW_CAP) });
    }
  };
  c.views = [];
  if (e.states.length <= VIEW_CAP) c.views.push({ label: 'all ' + e.states.length + ' states', ids: e.states.map((s) => s.id) });
  e.cycles.forEach((ids, i) => paged('cycle ' + (i + 1) + ' (' + ids.length + ' states)', ids));
  transient.forEach((t, i) => paged('transient cycle ' + (i + 1) + ' (' + t.states.length + ' states, cannot repeat)', t.states));
  if (e.terminal.length) paged('terminal states (' + e.terminal.length + (rests.size ? ', ' + rests.size + ' possible rests' : '') + ')', e.terminal);
  if (others.length) paged('other states (' + others.length + ')', others);
  return c;
}

// The states around one: itself, then breadth first along transitions either way, up to the cap.
function around(c, id) {
  const seen = new Set([id]);
  for (let frontier = [id], depth = 0; depth < 2 && frontier.length; depth++) {
    const next = [];
    for (const s of frontier) {
      for (const t of (c.next.get(s) || []).concat(c.prev.get(s) || [])) {
        const o = t.from === s ? t.to : t.from;
        if (!seen.has(o) && seen.size < VIEW_CAP) { seen.add(o); next.push(o); }
      }
    }
    frontier = next;
  }
  return { label: 'around #' + id + ' (' + seen.size + ' states)', ids: [...seen] };
}

// A group's states in the order of its transitions: from its least id, on to a next state of the
// group not yet placed (the least), else to the least not yet placed; so a cycle reads round its ring.
function orderAlong(c, members) {
  const left = new Set(members), order = [];
  for (let s = Math.min(...members); left.size;) {
    left.delete(s);
    order.push(s);
    const next = (c.next.get(s) || []).map((t) => t.to).filter((t) => left.has(t));
    if (left.size) s = next.length ? Math.min(...next) : Math.min(...left);
  }
  return order;
}

// Layout: one box per group (a cycle's states on a ring, a large cycle's and the others in a grid),
// boxes in rows.
function layoutGraph(c, ids) {
  const groups = new Map();
  for (const id of ids) push(groups, c.group.has(id) ? c.group.get(id) : 'other', id);
  const rank = (k) => (typeof k === 'number' ? k : k.startsWith('transient-') ? 5e8 + Number(k.slice(10)) : k === 'terminal' ? 1e9 : 2e9);
  const order = [...groups.keys()].sort((a, b) => rank(a) - rank(b));
  const width = 900, at = new Map(), boxes = [];
  let x = 0, y = 0, rowHeight = 0;
  for (const key of order) {
    const members = orderAlong(c, groups.get(key));
    let w, h, place;
    if (typeof key === 'number' && members.length <= 40) {
      const r = Math.max(28, members.length * 30 / (2 * Math.PI));
      w = h = 2 * r + 44;
      place = (i) => [w / 2 + r * Math.cos(2 * Math.PI * i / members.length - Math.PI / 2),
                      h / 2 + 8 + r * Math.sin(2 * Math.PI * i / members.length - Math.PI / 2)];
    } else {  // rows back and forth, so that consecutive states stay side by side
      const cols = Math.max(1, Math.min(members.length, Math.ceil(Math.sqrt(members.length * 2))));
      w = cols * 34 + 20;
      h = Math.ceil(members.length / cols) * 34 + 36;
      place = (i) => {
        const row = Math.floor(i / cols), col = row % 2 ? cols - 1 - (i % cols) : i % cols;
        return [27 + col * 34, 44 + row * 34];
      };
    }
    if (x > 0 && x + w > width) { x = 0; y += rowHeight + 12; rowHeight = 0; }
    boxes.push({ key, x, y, w, h, n: members.length });
    members.forEach((id, i) => { const p = place(i); at.set(id, [x + p[0], y + p[1]]); });
    x += w + 12;
    rowHeight = Math.max(rowHeight, h);
  }
  return { at, boxes, width: Math.max(width, ...boxes.map((b) => b.x + b.w)), height: y + rowHeight + 4 };
}

function drawGraph() {
  const c = graph.chain, v = graph.view, { at, boxes, width, height } = layoutGraph(c, v.ids);
  const colour = (t) => (t.causes.includes('collision') ? '#c0392b' : t.causes.includes('dynamic') ? '#2c6fbb' : '#333333');
  let svg = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ' + width + ' ' + Math.max(height, 60) + '">' +
    '<defs>' + ['#c0392b', '#2c6fbb', '#333333'].map((col, i) => '<marker id="arrow' + i + '" viewBox="0 0 10 10" refX="10" refY="5" ' +
      'markerWidth="6" markerHeight="6" orient="auto"><path d="M0,0L10,5L0,10z" fill="' + col + '"/></marker>').join('') + '</defs>';
  for (const b of boxes) {
    const label = typeof b.key === 'number' ? 'cycle ' + (b.key + 1) : b.key.startsWith('transient-') ? 'transient cycle ' + (Number(b.key.slice(10)) + 1) +
      ' (cannot repeat)' : b.key === 'terminal' ? 'terminal states' : 'other states';
    svg += '<g class="group"><rect x="' + b.x + '" y="' + b.y + '" width="' + b.w + '" height="' + b.h + '" rx="10" fill="none" stroke="#bbbbbb"/>' +
      '<text x="' + (b.x + 8) + '" y="' + (b.y + 15) + '" font-size="11" fill="#555555">' + label + ' (' + b.n + ')</text></g>';
  }
  for (const id of v.ids) {
    for (const t of c.next.get(id) || []) {
      if (!at.has(t.to)) continue;
      const [x1, y1] = at.get(t.from), [x2, y2] = at.get(t.to), style = ' stroke="' + colour(t) + '"' +
        (t.duration === 'instant' ? ' stroke-dasharray="4,2"' : '') + ' marker-end="url(#arrow' + ['#c0392b', '#2c6fbb', '#333333'].indexOf(colour(t)) + ')"';
      if (t.from === t.to) {
        svg += '<path class="edge" d="M' + (x1 - 5) + ',' + (y1 - 10) + 'a8,8 0 1,1 10,0" fill="none"' + style + '/>';
        continue;
      }
      const d = Math.hypot(x2 - x1, y2 - y1), ux = (x2 - x1) / d, uy = (y2 - y1) / d;
      svg += '<line class="edge" data-from="' + t.from + '" data-to="' + t.to + '" x1="' + (x1 + 11 * ux).toFixed(1) + '" y1="' +
        (y1 + 11 * uy).toFixed(1) + '" x2="' + (x2 - 12 * ux).toFixed(1) + '" y2="' + (y2 - 12 * uy).toFixed(1) + '"' + style + '/>';
    }
  }
  const terminal = new Set(c.e.terminal);
  for (const id of v.ids) {
    const [x, y] = at.get(id);
    svg += '<g class="state" data-state="' + id + '"><title>' + escape(idText(c, id)) + '</title>' +
      (terminal.has(id) ? '<circle cx="' + x + '" cy="' + y + '" r="14" fill="none" stroke="#333333"/>' : '') +
      '<circle cx="' + x + '" cy="' + y + '" r="11"/><text x="' + x + '" y="' + (y + 3) + '" text-anchor="middle" font-size="9">' + id + '</text></g>';
  }
  byId('graph').innerHTML = svg + '</svg>';
  byId('graph-note').textContent = c.e.states.length > VIEW_CAP
    ? 'Chain ' + c.e.index + ' has ' + c.e.states.length + ' states: shown ' + VIEW_CAP + ' at most at a time; pick a group, or a state to see those around it.'
    : '';
  markGraph();
}

function markGraph() {
  const c = graph.chain, id = graph.state;
  const next = new Set((c.next.get(id) || []).map((t) => t.to)), prev = new Set((c.prev.get(id) || []).map((t) => t.from));
  const played = new Set(play.states);
  for (const g of byId('graph').querySelectorAll('g.state')) {
    const s = Number(g.getAttribute('data-state'));
    g.classList.toggle('selected', s === id);
    g.classList.toggle('next', next.has(s));
    g.classList.toggle('previous', prev.has(s));
    g.classList.toggle('played', played.has(s));
  }
}

function setView(v) {
  graph.view = v;
  const select = byId('graph-view');
  select.innerHTML = graph.chain.views.concat(graph.chain.views.includes(v) ? [] : [v])
    .map((w, i) => '<option value="' + i + '">' + escape(w.label) + '</option>').join('');
  select.value = String(graph.chain.views.includes(v) ? graph.chain.views.indexOf(v) : graph.chain.views.length);
  select.extra = graph.chain.views.includes(v) ? null : v;
  drawGraph();
}

function showChain(k) {
  graph.chain = prepareChain(k);
  graph.state = null;
  play.states = [];
  play.at = -1;
  byId('chains').querySelectorAll('button').forEach((b, i) => b.setAttribute('aria-pressed', String(i === k)));
  byId('state-drawing').innerHTML = graph.chain.d.drawing_svg;
  byId('state-drawing').querySelector('svg').insertAdjacentHTML('beforeend',
    '<g class="motions" transform="' + graph.chain.d.world_transform + '"></g>');
  byId('state-pair').innerHTML = graph.chain.d.pairs.map((p, i) =>
    '<option value="' + i + '">' + escape(data.pairs[p.pair].parts.join(' \u2013 ')) + '</option>').join('');
  setView(graph.chain.views[0]);
  showStatePair(0);
  showState(graph.chain.e.states.length ? graph.chain.e.states[0].id : null);
}

// The configuration space of one of the chain's pairs, where the state's point is drawn.
function showStatePair(i) {
  const p = data.pairs[graph.chain.d.pairs[i].pair];
  byId('state-pair').value = String(i);
  // A second copy of a picture: its clip path gets its own id.
  byId('state-cspace').innerHTML = p.cspace_svg.replace(/id="frame"/g, 'id="frame-state"').replace(/url\(#frame\)/g, 'url(#frame-state)');
  if (graph.state !== null) showState(graph.state);
}

function cspacePoint(svg, pair, q) {
  const f = svg.querySelector('rect.frame'), axes = pair.vocabulary.axes;
  const [x, y, w, h] = ['x', 'y', 'width', 'height'].map((a) => Number(f.getAttribute(a)));
  return [x + w * (q[0] - axes[0].lo) / (axes[0].hi - axes[0].lo), y + h - h * (q[1] - axes[1].lo) / (axes[1].hi - axes[1].lo)];
}

function transitionText(t, other) {
  return '<li><button data-state="' + other + '">' + escape(idText(graph.chain, other)) + '</button> (' + t.duration + '; ' +
    t.causes.join(', ') + ')</li>';
}

function showState(id) {
  const c = graph.chain;
  graph.state = id;
  if (id === null) return;
  const s = c.byId.get(id), drawing = byId('state-drawing');
  if (!graph.view.ids.includes(id)) setView(play.states.includes(id) && play.view ? play.view : around(c, id));
  // Each part where the first of the chain's pairs that holds it puts it (cli/state_drawing.hpp).
  const transforms = new Map();
  let contacts = '';
  c.d.pairs.forEach((cp, k) => {
    const pair = data.pairs[cp.pair], place = s.places[k].place;
    pair.parts.forEach((name, i) => { if (!transforms.has(name)) transforms.set(name, pair.samples[place].transforms[i]); });
    contacts += cp.contacts_svg[place];
  });
  for (const [name, t] of transforms) {
    const g = drawing.querySelector('g.part[data-part="' + CSS.escape(name) + '"]');
    if (g) g.setAttribute('transform', t);
  }
  drawing.querySelector('g.contacts').innerHTML = contacts;
  const motions = drawing.querySelector('g.motions');
  motions.innerHTML = c.e.objects.map((o) => (c.d.arrows[o] || {})[s.motions[o].slice(1, -1)] || '').join('');
  for (const a of motions.querySelectorAll('g.motion')) a.setAttribute('transform', transforms.get(a.getAttribute('data-part')) || '');
  drawing.setAttribute('data-state', String(id));
  byId('state-caption').textContent = 'State ' + idText(c, id);
  // The point in the configuration space, and the history's trail.
  const pi = Number(byId('state-pair').value), pair = data.pairs[c.d.pairs[pi].pair], svg = byId('state-cspace').querySelector('svg');
  for (const e of svg.querySelectorAll('.selected')) e.classList.remove('selected');
  for (const e of svg.querySelectorAll('[data-place="' + s.places[pi].place + '"]')) e.classList.add('selected');
  const points = (play.at >= 0 ? play.states.slice(0, play.at + 1) : [id]).map((h) =>
    cspacePoint(svg, pair, pair.samples[c.byId.get(h).places[pi].place].q));
  const old = svg.querySelector('g.state-point');
  if (old) old.remove();
  const [px, py] = points[points.length - 1];
  svg.insertAdjacentHTML('beforeend', '<g class="state-point"><polyline points="' + points.map((p) => p.join(',')).join(' ') +
    '" fill="none" stroke="#d35400" stroke-width="1.5" stroke-dasharray="3,2"/><circle cx="' + px + '" cy="' + py +
    '" r="7" fill="#d35400" fill-opacity="0.8" stroke="#000000"/></g>');
  const signs = (m) => c.e.objects.map((o) => escape(o) + ' ' + m[o].slice(1, -1)).join(', ');
  byId('state-info').innerHTML = '<p><b>' + escape(idText(c, id)) + '</b>' +
    (c.group.get(id) === 'terminal' ? ' (terminal: nothing changes any more)' : typeof c.group.get(id) === 'number' ? ' (on cycle ' + (c.group.get(id) + 1) + ')' :
      typeof c.group.get(id) === 'string' ? ' (on transient cycle ' + (Number(c.group.get(id).slice(10)) + 1) + ': it cannot repeat, ' +
      escape(c.transient[Number(c.group.get(id).slice(10))].object) + ' moves ' + c.transient[Number(c.group.get(id).slice(10))].motion.slice(1, -1) +
      ' throughout)' : '') + (c.rests.has(id) ? ' (a possible rest: it may stay, or move on)' : '') +
    '</p><p>Motions: ' + signs(s.motions) + '; net force: ' + signs(s.net_force) + '.</p>' +
    '<p>Next states:</p><ul id="state-next">' + ((c.next.get(id) || []).map((t) => transitionText(t, t.to)).join('') || '<li>none</li>') + '</ul>' +
    '<p>Previous states:</p><ul id="state-previous">' + ((c.prev.get(id) || []).map((t) => transitionText(t, t.from)).join('') || '<li>none</li>') + '</ul>';
  byId('state-id').value = String(id);
  markGraph();
}

// A history: state ids of the chain, `...` between two meaning the shortest path between them.
function shortestPath(c, from, to) {
  const back = new Map([[from, null]]);
  for (let queue = [from]; queue.length && !back.has(to);) {
    const s = queue.shift();
    for (const t of c.next.get(s) || []) if (!back.has(t.to)) { back.set(t.to, s); queue.push(t.to); }
  }
  if (!back.has(to)) return null;
  const path = [];
  for (let s = to; s !== null; s = back.get(s)) path.unshift(s);
  return path;
}

function parseHistory(text) {
  const c = graph.chain, words = text.trim().split(/\s+/).filter((w) => w), states = [];
  let gap = false;
  for (const w of words) {
    if (w === '...' || w === '\u2026') { gap = true; continue; }
    const id = Number(w.replace(/^#/, ''));
    if (!/^#?\d+$/.test(w) || !c.byId.has(id)) throw new Error("'" + w + "' is no state of chain " + c.e.index);
    const last = states[states.length - 1];
    if (gap) {
      if (last === undefined) throw new Error("'...' goes between two states");
      const path = shortestPath(c, last, id);
      if (!path) throw new Error('no path from #' + last + ' to #' + id);
      states.push(...path.slice(1));
    } else {
      if (last !== undefined && !(c.next.get(last) || []).some((t) => t.to === id)) throw new Error('no transition from #' + last + ' to #' + id);
      states.push(id);
    }
    gap = false;
  }
  if (!states.length) throw new Error('enter state ids, e.g. "#3 #7 #12", or "#3 ... #12"');
  return states;
}

function playStep(at) {
  play.at = at;
  const id = play.states[at];
  byId('history-status').textContent = 'step ' + (at + 1) + ' of ' + play.states.length + ': ' + idText(graph.chain, id);
  byId('history-status').setAttribute('data-step', String(at));
  showState(id);
}

function stopPlay() {
  clearInterval(play.timer);
  play.timer = null;
  byId('history-play').textContent = 'Play';
}

function loadHistory() {
  stopPlay();
  try {
    play.states = parseHistory(byId('history-input').value);
  } catch (e) {
    play.states = [];
    play.at = -1;
    byId('history-status').textContent = e.message;
    return false;
  }
  play.at = -1;
  const unique = [...new Set(play.states)];
  play.view = { label: 'the history (' + unique.length + ' states)', ids: unique.slice(0, VIEW_CAP) };
  setView(play.view);
  return true;
}

function startPlay() {
  if (play.timer) return stopPlay();
  if (!loadHistory()) return;
  playStep(0);
  byId('history-play').textContent = 'Stop';
  play.timer = setInterval(() => (play.at + 1 < play.states.length ? playStep(play.at + 1) : stopPlay()), Math.max(50, Number(byId('history-speed').value) || 800));
}

function startEnvisionment() {
  if (!env || !env.chains.length) return;
  for (const id of ['envision-panel', 'state-panel', 'history-panel']) byId(id).hidden = false;
  byId('chains').innerHTML = env.chains.map((c, k) => '<button data-chain="' + k + '">chain ' + c.index + ': ' +
    escape(c.objects.join(', ')) + ' (' + c.states.length + ' states)</button>').join('');
  byId('chains').addEventListener('click', (e) => { const b = e.target.closest('button[data-chain]'); if (b) { stopPlay(); showChain(Number(b.getAttribute('data-chain'))); } });
  byId('graph-view').addEventListener('change', (e) => setView(e.target.extra && Number(e.target.value) === graph.chain.views.length
    ? e.target.extra : graph.chain.views[Number(e.target.value)]));
  byId('graph').addEventListener('click', (e) => { const g = e.target.closest('g.state'); if (g) showState(Number(g.getAttribute('data-state'))); });
  byId('state-info').addEventListener('click', (e) => { const b = e.target.closest('button[data-state]'); if (b) showState(Number(b.getAttribute('data-state'))); });
  byId('state-pair').addEventListener('change', (e) => showStatePair(Number(e.target.value)));
  byId('state-go').addEventListener('click', () => {
    const id = Number(byId('state-id').value);
    if (graph.chain.byId.has(id)) showState(id);
  });
  byId('history-paths').innerHTML = '<option value="">type state ids, or pick a described behaviour</option>' + data.paths.map((p, i) =>
    '<option value="' + i + '">chain ' + p.chain + ': ' + escape(p.description) + (p.states.length ? ' (' + p.states.length + ' states)' : ' (no path)') + '</option>').join('');
  byId('history-paths').addEventListener('change', (e) => {
    const p = data.paths[Number(e.target.value)];
    if (!p) return;
    showChain(env.chains.findIndex((c) => c.index === p.chain));
    byId('history-input').value = p.states.map((s) => '#' + s).join(' ');
    loadHistory();
  });
  byId('history-play').addEventListener('click', startPlay);
  byId('history-back').addEventListener('click', () => { stopPlay(); if (play.at > 0 || loadHistory()) playStep(Math.max(0, play.at - 1)); });
  byId('history-forward').addEventListener('click', () => {
    stopPlay();
    if (play.at < 0 && !loadHistory()) return;
    playStep(Math.min(play.states.length - 1, play.at + 1));
  });
  byId('history-input').addEventListener('change', () => { stopPlay(); play.at = -1; });
  showChain(0);
}

startEnvisionment();
