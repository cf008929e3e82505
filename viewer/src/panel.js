// The side panel: colouring mode, groups with their checkboxes, clipping plane, quality
// histogram, element counts and worst elements. It edits the state and calls `changed`.

import { groupColor, hexOf } from './colors.js';
import { drawHistogram, qualitySummary } from './quality.js';

function el(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) {
    if (key === 'text') node.textContent = value;
    else if (key.startsWith('on')) node.addEventListener(key.slice(2), value);
    else node.setAttribute(key, value);
  }
  for (const child of children) if (child) node.append(child);
  return node;
}

function section(title, ...children) {
  return el('section', {}, el('h2', { text: title }), ...children);
}

const kMeasureNames = { gamma: 'gamma', sicn: 'SICN' };

function groupLabel(group) {
  const kinds = ['point', 'curve', 'surface', 'volume'];
  const what = group.physical ? `physical ${kinds[group.dim]} ${group.tag}` : `${kinds[group.dim]}`;
  return group.name ? `${group.name} (${what})` : `${what}${group.physical ? '' : ' ' + group.tag}`;
}

function groupList(mesh, state, changed) {
  const list = el('ul', { id: 'groups' });
  mesh.groups.forEach((group, g) => {
    const color = hexOf(groupColor(g));
    const box = el('input', { type: 'checkbox', 'data-group': String(g) });
    box.checked = state.groupOn[g];
    box.addEventListener('change', () => {
      state.groupOn[g] = box.checked;
      changed();
    });
    const swatch = el('span', {
      class: 'swatch',
      'data-color': color,
      style: `background:${color}`,
    });
    list.append(el('li', { class: 'group' }, el('label', {}, box, swatch, groupLabel(group))));
  });
  return section(mesh.groupsArePhysical ? 'Physical groups' : 'Entities', list);
}

function modeControls(mesh, state, changed) {
  const radio = (value, label) => {
    const input = el('input', { type: 'radio', name: 'mode', id: `mode-${value}`, value });
    input.checked = state.mode === value;
    input.addEventListener('change', () => {
      state.mode = value;
      changed();
    });
    return el('label', {}, input, label);
  };
  const measure = el('select', { id: 'measure' });
  for (const m of mesh.measures)
    measure.append(el('option', { value: m, text: kMeasureNames[m] || m }));
  measure.value = state.measure;
  measure.addEventListener('change', () => {
    state.measure = measure.value;
    changed();
  });
  const edges = el('input', { type: 'checkbox', id: 'edges' });
  edges.checked = state.edges;
  edges.addEventListener('change', () => {
    state.edges = edges.checked;
    changed();
  });
  return section(
    'Colour',
    el('div', { class: 'row' }, radio('groups', 'groups'), radio('quality', 'quality'), measure),
    el('div', { class: 'row' }, el('label', {}, edges, 'element edges')),
  );
}

// `cameraSide(axis)`: where the camera is along the axis, from the view's centre; choosing an
// axis keeps the half away from the camera, so that the cut faces it.
function clipControls(mesh, state, changed, cameraSide) {
  const axis = el('select', { id: 'clip-axis' });
  ['off', 'x', 'y', 'z'].forEach((name, i) =>
    axis.append(el('option', { value: String(i - 1), text: name })),
  );
  const slider = el('input', {
    type: 'range',
    id: 'clip-position',
    min: '0',
    max: '1000',
    value: '500',
  });
  const flip = el('input', { type: 'checkbox', id: 'clip-flip' });
  const apply = () => {
    state.clip.axis = Number(axis.value);
    state.clip.flip = flip.checked;
    const a = Math.max(0, state.clip.axis);
    const { min, max } = mesh.bounds;
    state.clip.position = min[a] + ((max[a] - min[a]) * Number(slider.value)) / 1000;
    slider.disabled = state.clip.axis < 0;
    changed();
  };
  slider.disabled = true;
  axis.addEventListener('change', () => {
    if (Number(axis.value) >= 0) flip.checked = cameraSide(Number(axis.value)) < 0;
    apply();
  });
  slider.addEventListener('input', apply);
  flip.addEventListener('change', apply);
  return section(
    'Clipping plane',
    el('div', { class: 'row' },
      el('label', {}, 'axis ', axis), el('label', {}, flip, 'other side')),
    slider,
    el('p', { class: 'note', text: 'Keeps the elements whose centre is on one side.' }),
  );
}

function countTable(mesh) {
  const body = el('tbody');
  for (const [type, count] of mesh.counts)
    body.append(el('tr', {}, el('td', { text: type }),
      el('td', { class: 'number', text: String(count) })));
  return section(
    'Elements',
    el('p', { text: `${mesh.nodeCount} nodes, ${mesh.elementCount} elements` }),
    el('table', { id: 'counts' }, body),
  );
}

export class Panel {
  constructor(root, mesh, state, changed, focus, cameraSide) {
    this.mesh = mesh;
    this.state = state;
    this.focus = focus;
    this.histogram = el('canvas', { id: 'histogram' });
    this.stats = el('p', { id: 'quality-stats' });
    this.worst = el('tbody');
    this.qualitySection = section('Quality', this.stats, this.histogram);
    this.qualitySection.id = 'quality';
    root.append(
      el('h1', { text: state.title }),
      el('p', { class: 'note', text: 'Drag to turn, right-drag to pan, wheel to zoom.' }),
      modeControls(mesh, state, changed),
      groupList(mesh, state, changed),
      clipControls(mesh, state, changed, cameraSide),
      this.qualitySection,
      countTable(mesh),
      section('Worst elements', el('table', { id: 'worst' },
        el('thead', {}, el('tr', {}, el('th', { text: 'id' }), el('th', { text: 'type' }),
          el('th', { text: 'quality' }))), this.worst)),
    );
  }

  // Shows what depends on the state: the histogram in quality mode, the worst elements.
  update() {
    const measure = this.state.measure;
    this.summaries ??= {};
    this.summaries[measure] ??= qualitySummary(this.mesh, measure);
    const summary = this.summaries[measure];
    const name = kMeasureNames[measure] || measure;
    this.qualitySection.hidden = this.state.mode !== 'quality';
    this.histogram.dataset.bins = summary.bins.join(' ');
    this.stats.textContent = summary.count
      ? `${name} over ${summary.count} elements: min ${summary.min.toFixed(3)}, ` +
        `mean ${summary.mean.toFixed(3)}`
      : 'No element to measure.';
    if (!this.qualitySection.hidden) drawHistogram(this.histogram, summary.bins);
    this.worst.replaceChildren(
      ...summary.worst.map(({ block, i, q }) => {
        const row = el('tr', { 'data-element': String(block.firstId + i) },
          el('td', { text: String(block.firstId + i) }), el('td', { text: block.type }),
          el('td', { class: 'number', text: q.toFixed(3) }));
        row.addEventListener('click', () => this.focus(block, i));
        return row;
      }),
    );
  }
}
