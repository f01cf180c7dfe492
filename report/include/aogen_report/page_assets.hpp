// aogen_report/page_assets.hpp — the style sheet and the script of the report's pages,
// inlined into each page (no network, no CDN, nothing to install).
//
//     html << "<style>" << aogen_report::page_style << "</style>";
//     html << "<script>" << aogen_report::page_script << "</script>";   // report.html only
//
// page_style   both pages (report.html, the stability suite's report.html)
// page_script  report.html's behaviour, reading what page.hpp writes:
//   - the data: JSON in <script type="application/json" id="aogen-data"> (variants with
//     their numbers per scene, scenes, and the images as data: URIs);
//   - hover or focus on a plot marker (.point, data-variant = index into data.variants):
//     the tooltip #tooltip names the variant with its time, p10–p90, errors, × floor and
//     per-pass times; a click or Enter selects it;
//   - the variants table #variant-table: a header button sorts by its column (numbers by
//     each cell's data-value, missing values last; again: the other way round); the
//     #filters selects hide rows whose data-technique/-resolution/-blur/-stage differ,
//     and fade their markers; a click or Enter on a row selects its variant;
//   - selecting a variant marks its row and markers and draws, per scene, reference |
//     variant | |error| on canvases (#strip-rows), as the report's PNG strips do: grey
//     levels, the error on black → purple → orange → yellow reaching yellow at 0.5
//     (images.hpp's heat()), background in blue-grey; a half-resolution AO image is shown
//     at full resolution by nearest upsampling.
// Errors are not caught and hidden: a broken page shows in the browser's console, which the
// page test (tests/report/page_test.cpp) reads.
#pragma once

namespace aogen_report {

inline constexpr const char* page_style = R"css(
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 14px; margin: 16px 24px; color: #1b1b1b; background: #ffffff; }
h1 { font-size: 22px; margin: 0 0 8px; }
h2 { font-size: 17px; margin: 24px 0 8px; border-bottom: 1px solid #d0d0d0; padding-bottom: 2px; }
ul.facts { margin: 0 0 8px; padding-left: 20px; }
p.how { max-width: 1100px; line-height: 1.4; color: #333333; }
code { font-family: "DejaVu Sans Mono", monospace; font-size: 12px; }
table { border-collapse: collapse; font-size: 12px; }
th, td { border: 1px solid #d8d8d8; padding: 2px 6px; }
th { background: #f0f0f0; position: sticky; top: 0; }
td.name { white-space: nowrap; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
td.mid, th.mid { text-align: center; }
th button { font: inherit; font-weight: bold; border: none; background: none; cursor: pointer; padding: 0; }
th[aria-sort="ascending"] button::after { content: " ▲"; }
th[aria-sort="descending"] button::after { content: " ▼"; }
#variant-table tbody tr { cursor: pointer; }
#variant-table tbody tr:hover { background: #f4f8ff; }
#variant-table tbody tr[aria-selected="true"] { background: #ffe9a8; }
.table-scroll { max-height: 520px; max-width: 100%; overflow: auto; border: 1px solid #d0d0d0; display: inline-block; }
#filters { margin: 8px 0; display: flex; gap: 16px; flex-wrap: wrap; align-items: center; }
#filters label { font-size: 13px; }
#plot svg { max-width: 100%; height: auto; }
#plot .point { cursor: pointer; }
#plot .point:focus { outline: none; stroke-width: 3; }
#plot .point.faded { opacity: 0.12; }
#plot .point.selected { stroke: #000000; stroke-width: 3; }
#tooltip { position: fixed; z-index: 10; background: #202020; color: #ffffff; padding: 6px 8px; border-radius: 4px; font-size: 12px;
           line-height: 1.35; pointer-events: none; max-width: 460px; }
#tooltip .name { font-family: "DejaVu Sans Mono", monospace; font-weight: bold; }
#strip-rows { display: flex; flex-direction: column; gap: 10px; }
.strip figcaption { font-size: 12px; margin-bottom: 2px; }
.strip .panels { display: flex; gap: 2px; }
.strip canvas { width: 320px; max-width: 32vw; image-rendering: pixelated; background: #283c5a; }
.suite-grid td.pass { background: #dff3df; text-align: center; }
.suite-grid td.fail { background: #f7c9c9; text-align: center; font-weight: bold; }
.suite-grid td.skip { color: #888888; text-align: center; }
.summary-fail { color: #b00000; }
)css";

inline constexpr const char* page_script = R"js(
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('aogen-data').textContent);
  const tooltip = document.getElementById('tooltip');
  const table = document.getElementById('variant-table');
  const rows = Array.from(table.tBodies[0].rows);
  const points = Array.from(document.querySelectorAll('#plot .point'));
  const filters = Array.from(document.querySelectorAll('#filters select'));
  const shown = document.getElementById('shown');
  const stripRows = document.getElementById('strip-rows');
  const stripsFor = document.getElementById('strips-for');

  const fixed = (x, digits) => (x === null || x === undefined || !isFinite(x)) ? '–' : Number(x).toFixed(digits);

  // --- the tooltip -------------------------------------------------------------------
  function tooltipLines(v) {
    const passes = v.passes.map((p, k) => p + ' ' + fixed(v.pass_ms[k], 3)).join(', ');
    return [
      fixed(v.ms, 3) + ' ms (p10–p90 ' + fixed(v.ms_p10, 3) + '–' + fixed(v.ms_p90, 3) + '), × floor ' + fixed(v.floor_ratio, 2),
      'RMSE ' + fixed(v.rmse, 4) + ' default, ' + fixed(v.rmse_calibrated, 4) + ' calibrated' +
        (data.frames > 1 ? ', ' + fixed(v.rmse_accumulated, 4) + ' after ' + data.frames + ' frames' : ''),
      'passes (ms): ' + passes
    ];
  }
  function showTooltip(point) {
    const v = data.variants[Number(point.dataset.variant)];
    tooltip.replaceChildren();
    const name = document.createElement('div');
    name.className = 'name';
    name.textContent = v.name;
    tooltip.appendChild(name);
    for (const line of tooltipLines(v)) {
      const div = document.createElement('div');
      div.textContent = line;
      tooltip.appendChild(div);
    }
    tooltip.hidden = false;
    const r = point.getBoundingClientRect();
    const left = Math.min(r.right + 10, window.innerWidth - tooltip.offsetWidth - 4);
    const top = r.top + tooltip.offsetHeight + 10 < window.innerHeight ? r.top + 10 : r.top - tooltip.offsetHeight - 10;
    tooltip.style.left = Math.max(4, left) + 'px';
    tooltip.style.top = Math.max(4, top) + 'px';
  }
  function hideTooltip() { tooltip.hidden = true; }

  for (const point of points) {
    // The page's tooltip replaces the SVG's own <title>, kept as the marker's accessible name.
    const title = point.querySelector('title');
    if (title) { point.setAttribute('aria-label', title.textContent); title.remove(); }
    point.addEventListener('mouseenter', () => showTooltip(point));
    point.addEventListener('focus', () => showTooltip(point));
    point.addEventListener('mouseleave', hideTooltip);
    point.addEventListener('blur', hideTooltip);
    point.addEventListener('click', () => select(Number(point.dataset.variant)));
    point.addEventListener('keydown', (e) => { if (e.key === 'Enter') select(Number(point.dataset.variant)); });
  }

  // --- sorting -------------------------------------------------------------------------
  const headers = Array.from(table.tHead.rows[0].cells);
  headers.forEach((th, column) => {
    const button = th.querySelector('button');
    if (button) button.addEventListener('click', () => sortBy(column));
  });
  function sortBy(column) {
    const th = headers[column];
    const ascending = th.getAttribute('aria-sort') !== 'ascending';
    for (const h of headers) h.removeAttribute('aria-sort');
    th.setAttribute('aria-sort', ascending ? 'ascending' : 'descending');
    const numeric = th.dataset.type === 'number';
    const key = (row) => row.cells[column].dataset.value;
    const order = rows.slice().sort((a, b) => {
      const x = key(a), y = key(b);
      if (x === '' || y === '') return (x === '') - (y === '');       // missing values last, either way
      const c = numeric ? Number(x) - Number(y) : x.localeCompare(y);
      return (ascending ? c : -c) || Number(a.dataset.variant) - Number(b.dataset.variant);
    });
    const body = table.tBodies[0];
    for (const row of order) body.appendChild(row);
  }

  // --- filtering -----------------------------------------------------------------------
  function applyFilters() {
    let count = 0;
    const visible = new Set();
    for (const row of rows) {
      const keep = filters.every((f) => f.value === '' || row.dataset[f.name] === f.value);
      row.hidden = !keep;
      if (keep) { count += 1; visible.add(row.dataset.variant); }
    }
    for (const point of points) point.classList.toggle('faded', !visible.has(point.dataset.variant));
    shown.textContent = count + ' of ' + rows.length + ' variants shown';
  }
  for (const f of filters) f.addEventListener('change', applyFilters);

  // --- selection and strips ------------------------------------------------------------
  for (const row of rows) {
    row.tabIndex = 0;
    row.addEventListener('click', () => select(Number(row.dataset.variant)));
    row.addEventListener('keydown', (e) => { if (e.key === 'Enter') select(Number(row.dataset.variant)); });
  }
  function select(index) {
    for (const row of rows) row.setAttribute('aria-selected', String(Number(row.dataset.variant) === index));
    for (const point of points) {
      const on = Number(point.dataset.variant) === index;
      point.classList.toggle('selected', on);
      if (on) point.parentNode.appendChild(point);                  // drawn last: on top
    }
    drawStrips(index);
  }

  const background = [40, 60, 90];
  const stops = [[0, 0, 0], [120, 28, 160], [240, 110, 30], [255, 250, 160]];
  function heat(error) {                                             // images.hpp's heat(), full scale 0.5
    const t = Math.min(Math.abs(error) / 0.5, 1) * 3;
    const i = Math.min(Math.floor(t), 2), f = t - i;
    return stops[i].map((s, k) => Math.round(s + f * (stops[i + 1][k] - s)));
  }
  function pixelsOf(image) {
    const c = document.createElement('canvas');
    c.width = image.naturalWidth; c.height = image.naturalHeight;
    const g = c.getContext('2d');
    g.drawImage(image, 0, 0);
    return g.getImageData(0, 0, c.width, c.height).data;
  }
  function loaded(uri) {
    return new Promise((resolve, reject) => {
      const image = new Image();
      image.onload = () => resolve(image);
      image.onerror = () => reject(new Error('an embedded image does not decode'));
      image.src = uri;
    });
  }
  // reference | variant | |error| of one scene, each as a canvas at the scene's size.
  async function panels(scene, reference, ao, factor) {
    const w = scene.width, h = scene.height;
    const ref = pixelsOf(await loaded(reference)), own = pixelsOf(await loaded(ao));
    const aoWidth = Math.ceil(w / factor);
    const images = [0, 1, 2].map(() => new ImageData(w, h));
    for (let y = 0; y < h; ++y)
      for (let x = 0; x < w; ++x) {
        const i = (y * w + x) * 4, valid = ref[i + 3] === 255;
        const r = ref[i], a = own[(Math.floor(y / factor) * aoWidth + Math.floor(x / factor)) * 4];
        const colours = valid ? [[r, r, r], [a, a, a], heat((a - r) / 255)] : [background, background, background];
        colours.forEach((c, k) => { images[k].data.set([c[0], c[1], c[2], 255], i); });
      }
    return images.map((image) => {
      const canvas = document.createElement('canvas');
      canvas.width = w; canvas.height = h;
      canvas.getContext('2d').putImageData(image, 0, 0);
      return canvas;
    });
  }
  let drawing = 0;
  async function drawStrips(index) {
    const ticket = ++drawing;
    const v = data.variants[index];
    stripsFor.textContent = v.name + ': reference | variant (default parameters) | |variant − reference| per scene';
    const figures = [];
    for (let s = 0; s < data.scenes.length; ++s) {
      const scene = data.scenes[s], run = v.runs[s];
      const figure = document.createElement('figure');
      figure.className = 'strip';
      figure.dataset.scene = String(s);
      const caption = document.createElement('figcaption');
      caption.textContent = run.skipped ? scene.name + ': not run (' + run.skipped + ')'
        : scene.name + ': ' + fixed(run.ms, 3) + ' ms, RMSE ' + fixed(run.rmse, 4) + ' default, ' + fixed(run.rmse_calibrated, 4) +
          ' calibrated (p ' + fixed(run.power, 2) + ')' + (data.frames > 1 ? ', ' + fixed(run.rmse_accumulated, 4) + ' after ' + data.frames + ' frames' : '');
      figure.appendChild(caption);
      if (!run.skipped) {
        const row = document.createElement('div');
        row.className = 'panels';
        for (const canvas of await panels(scene, data.images.reference[s], data.images.ao[index][s], run.factor)) row.appendChild(canvas);
        if (ticket !== drawing) return;                              // another variant was selected meanwhile
        figure.appendChild(row);
      }
      figures.push(figure);
    }
    stripRows.replaceChildren(...figures);
    stripRows.dataset.variant = String(index);
  }

  applyFilters();
  document.body.dataset.ready = 'true';
})();
)js";

} // namespace aogen_report
