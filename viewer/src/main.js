// The mesh viewer's entry point: reads the mesh the page carries, lays out the panel and the
// view, and redraws when a control changes. Everything runs from the page itself, offline.

import css from './style.css';
import { readMesh } from './data.js';
import { visibleGeometry } from './faces.js';
import { Panel } from './panel.js';
import { MeshView } from './scene.js';

function pageTitle() {
  const name = decodeURIComponent(window.location.pathname.split('/').pop() || '');
  return name || 'mesh';
}

function fail(message) {
  const note = document.createElement('p');
  note.className = 'failure';
  note.textContent = `This mesh cannot be shown: ${message}`;
  document.body.replaceChildren(note);
  document.body.dataset.ready = 'failed';
}

function start() {
  const style = document.createElement('style');
  style.textContent = css;
  document.head.append(style);
  const mesh = readMesh();
  const state = {
    title: pageTitle(),
    mode: 'groups',
    measure: mesh.measures[0],
    edges: true,
    groupOn: mesh.groups.map(() => true),
    clip: { axis: -1, position: 0, flip: false },
  };
  document.title = `${state.title} - geomesh`;
  const panelRoot = document.createElement('aside');
  panelRoot.id = 'panel';
  const canvas = document.createElement('canvas');
  canvas.id = 'view';
  document.body.append(panelRoot, canvas);
  const view = new MeshView(canvas, mesh);
  let panel = null;
  const redraw = () => {
    const geometry = visibleGeometry(mesh, state);
    view.show(geometry, state.edges);
    canvas.dataset.kept = String(geometry.keptCount);
    if (panel) panel.update();
  };
  const focus = (block, i) => {
    const k = block.corners;
    view.focus(Array.from(block.nodes.subarray(i * k, i * k + k)), block.edges);
  };
  const cameraSide = (axis) =>
    view.camera.position.getComponent(axis) - view.controls.target.getComponent(axis);
  panel = new Panel(panelRoot, mesh, state, redraw, focus, cameraSide);
  new ResizeObserver(() => view.resize()).observe(canvas);
  view.resize();
  redraw();
  window.geomeshViewer = { mesh, state, view, redraw };
  document.body.dataset.ready = 'yes';
}

try {
  start();
} catch (error) {
  fail(error && error.message ? error.message : String(error));
}
