/// @file html_viewer.cpp
#include "frames/html_viewer.h"

#include <algorithm>
#include <utility>

#include <nlohmann/json.hpp>

#include "image/file_io.h"
#include "golden/report.h"

namespace impulse2d::demos {
namespace {

/// The page. @TITLE@, @DETAILS@, @WIDTH@, @HEIGHT@ and @DATA@ (frames and variants as JSON) are
/// filled in by `html_viewer_page`; everything else is fixed.
constexpr const char* page_template = R"html(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>@TITLE@</title>
<style>
  body { font: 14px system-ui, sans-serif; margin: 16px; background: #f4f4f4; color: #222; }
  h1 { font-size: 18px; margin: 0 0 4px; }
  #details { color: #555; margin: 0 0 12px; }
  #frame { display: block; max-width: 100%; height: auto; background: #fff; border: 1px solid #bbb; }
  #controls { display: flex; align-items: center; gap: 8px; margin: 8px 0; max-width: @WIDTH@px; }
  #scrub { flex: 1; }
  #play { width: 5em; }
  #readout { font-variant-numeric: tabular-nums; margin: 4px 0 8px; }
  #readout span { margin-right: 1.5em; }
  #timeline { display: block; width: 100%; max-width: @WIDTH@px; height: 90px; background: #fff;
              border: 1px solid #bbb; cursor: crosshair; }
  #legend { color: #555; margin-top: 4px; }
  .energy { color: #1f5fbf; } .contacts { color: #d2691e; }
  .touch { color: #007878; } .hit { color: #be0000; } .sensor { color: #a08200; }
  #keys { color: #777; margin-top: 12px; }
  #overlays { border: 1px solid #bbb; margin: 8px 0; max-width: @WIDTH@px; }
  #overlays label { margin-right: 1em; white-space: nowrap; }
</style>
</head>
<body data-frame="0">
<h1>@TITLE@</h1>
<p id="details">@DETAILS@</p>
<img id="frame" width="@WIDTH@" height="@HEIGHT@" alt="frame">
<div id="controls">
  <button id="play" type="button">play</button>
  <input id="scrub" type="range" min="0" max="0" step="1" value="0" aria-label="frame">
</div>
<div id="readout">
  <span>frame <b id="frame-number"></b></span>
  <span>step <b id="step"></b></span>
  <span>time <b id="time"></b> s</span>
  <span class="energy">energy <b id="energy"></b> J</span>
  <span class="contacts">contacts <b id="contacts"></b></span>
  <span id="events-readout" hidden>events <b id="events"></b></span>
</div>
<svg id="timeline" preserveAspectRatio="none" role="img" aria-label="energy and contacts over the run">
  <polyline id="energy-line" fill="none" stroke="#1f5fbf" stroke-width="1.5" vector-effect="non-scaling-stroke"/>
  <polyline id="contacts-line" fill="none" stroke="#d2691e" stroke-width="1.5" vector-effect="non-scaling-stroke"/>
  <g id="event-ticks"></g>
  <line id="marker" y1="0" y2="1" stroke="#c00" stroke-width="2" vector-effect="non-scaling-stroke"/>
</svg>
<div id="legend"></div>
<fieldset id="overlays" hidden><legend>overlays (pre-rendered: switching needs no new render)</legend></fieldset>
<div id="keys">Click the timeline to jump to a frame. Keys: left/right arrow one frame,
  space play/pause, Home/End first/last frame. <code>#frame=N</code> in the address opens frame N,
  <code>#frame=N&amp;overlays=NAME</code> with those overlays.</div>
<script type="application/json" id="viewer-data">@DATA@</script>
<script>
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('viewer-data').textContent);
  const frames = data.frames, variants = data.variants;
  const last = frames.length - 1;
  const byId = (id) => document.getElementById(id);
  const image = byId('frame'), scrub = byId('scrub'), play = byId('play');
  const timeline = byId('timeline'), marker = byId('marker');
  // Real time: the simulated time between the first two frames, within 1..120 frames/s.
  const interval = frames.length > 1
      ? Math.min(1000, Math.max(1000 / 120, (frames[1].time - frames[0].time) * 1000)) : 100;
  let current = 0;
  let timer = null;
  let variant = variants.length > 0 ? variants[0] : { label: '', directory: '' };
  const path = (f) => (variant.directory === '' ? '' :
      variant.directory.split('/').map(encodeURIComponent).join('/') + '/') + encodeURIComponent(f.file);

  const number = (value, digits) => value === null ? 'n/a' : Number(value.toPrecision(digits)).toString();

  function describeEvents(e) {
    const parts = [[e.touch_begin, 'begin'], [e.touch_end, 'end'], [e.hit, 'hit'],
                   [e.sensor_begin, 'sensor in'], [e.sensor_end, 'sensor out']]
        .filter(([n]) => n > 0).map(([n, name]) => n + ' ' + name);
    return parts.length > 0 ? parts.join(', ') : 'none';
  }

  function show(n) {
    current = Math.max(0, Math.min(last, n));
    const f = frames[current];
    image.src = path(f);
    image.alt = 'frame ' + f.frame + ', step ' + f.step;
    scrub.value = current;
    byId('frame-number').textContent = f.frame + ' / ' + last;
    byId('step').textContent = f.step;
    byId('time').textContent = number(f.time, 6);
    byId('energy').textContent = number(f.energy, 6);
    byId('contacts').textContent = f.contacts;
    if (f.events) byId('events').textContent = describeEvents(f.events);
    marker.setAttribute('x1', current);
    marker.setAttribute('x2', current);
    document.body.dataset.frame = current;
    document.body.dataset.overlays = variant.label;
  }

  // The overlay switch: one radio button per variant.
  const switcher = byId('overlays');
  function choose(label) {
    const found = variants.find((v) => v.label === label);
    if (!found) return;
    variant = found;
    switcher.querySelectorAll('input').forEach((input) => { input.checked = input.value === label; });
  }
  if (variants.length > 1) {
    switcher.hidden = false;
    variants.forEach((v) => {
      const label = document.createElement('label');
      const input = document.createElement('input');
      input.type = 'radio';
      input.name = 'overlays';
      input.value = v.label;
      input.addEventListener('change', () => { choose(v.label); show(current); });
      label.append(input, ' ' + v.label);
      switcher.append(label);
    });
    choose(variant.label);
  }

  function setPlaying(on) {
    if (timer !== null) clearInterval(timer);
    timer = null;
    play.textContent = on ? 'pause' : 'play';
    if (!on) return;
    if (current === last) show(0);
    timer = setInterval(() => {
      if (current >= last) { setPlaying(false); return; }
      show(current + 1);
    }, interval);
  }

  // The timeline: x is the frame number, y each series scaled to its own range.
  function plot(id, key) {
    const values = frames.map((f) => f[key]).filter((v) => v !== null);
    if (values.length === 0) return [0, 0];
    const low = Math.min(...values), high = Math.max(...values);
    const span = high > low ? high - low : 1;
    const points = [];
    frames.forEach((f, i) => {
      if (f[key] !== null) points.push(i + ',' + (0.95 - 0.9 * (f[key] - low) / span));
    });
    byId(id).setAttribute('points', points.join(' '));
    return [low, high];
  }
  timeline.setAttribute('viewBox', '0 0 ' + Math.max(1, last) + ' 1');
  const energy = plot('energy-line', 'energy'), contacts = plot('contacts-line', 'contacts');
  byId('legend').innerHTML = '<span class="energy">energy ' + number(energy[0], 4) + ' .. ' +
      number(energy[1], 4) + ' J</span> &nbsp; <span class="contacts">contacts ' + contacts[0] +
      ' .. ' + contacts[1] + '</span>';
  // With the events overlay: one tick per frame with events of each kind, in three rows at the
  // top (touch begin or end, hit, sensor begin or end), and the frame's events in the readout.
  if (frames.length > 0 && frames[0].events) {
    byId('events-readout').hidden = false;
    const rows = [['touch', '#007878', (e) => e.touch_begin + e.touch_end],
                  ['hit', '#be0000', (e) => e.hit],
                  ['sensor', '#a08200', (e) => e.sensor_begin + e.sensor_end]];
    const ticks = byId('event-ticks'), totals = [0, 0, 0];
    frames.forEach((f, i) => {
      rows.forEach(([, colour, count], row) => {
        const n = count(f.events);
        if (n === 0) return;
        totals[row] += n;
        const tick = document.createElementNS(timeline.namespaceURI, 'line');
        tick.setAttribute('x1', i);
        tick.setAttribute('x2', i);
        tick.setAttribute('y1', 0.02 + 0.1 * row);
        tick.setAttribute('y2', 0.1 + 0.1 * row);
        tick.setAttribute('stroke', colour);
        tick.setAttribute('stroke-width', '2');
        tick.setAttribute('vector-effect', 'non-scaling-stroke');
        ticks.append(tick);
      });
    });
    byId('legend').innerHTML += ' &nbsp; events (ticks): ' + rows.map(([name], row) =>
        '<span class="' + name + '">' + name + ' ' + totals[row] + '</span>').join(' &nbsp; ');
  }

  timeline.addEventListener('click', (event) => {
    const box = timeline.getBoundingClientRect();
    setPlaying(false);
    show(Math.round((event.clientX - box.left) / box.width * last));
  });
  scrub.max = last;
  scrub.addEventListener('input', () => { setPlaying(false); show(Number(scrub.value)); });
  play.addEventListener('click', () => setPlaying(timer === null));
  document.addEventListener('keydown', (event) => {
    const moves = { ArrowLeft: current - 1, ArrowRight: current + 1, Home: 0, End: last };
    if (event.key in moves) {
      setPlaying(false);
      show(moves[event.key]);
    } else if (event.key === ' ') {
      setPlaying(timer === null);
    } else {
      return;
    }
    event.preventDefault();
  });
  function openFromAddress() {
    const overlays = /overlays=([^&]*)/.exec(location.hash);
    if (overlays) choose(decodeURIComponent(overlays[1]));
    const match = /frame=(\d+)/.exec(location.hash);
    show(match ? Number(match[1]) : current);
  }
  window.addEventListener('hashchange', openFromAddress);
  openFromAddress();
})();
</script>
</body>
</html>
)html";

/// `text` with every `placeholder` replaced by `value`.
std::string replace_all(std::string text, const std::string& placeholder, const std::string& value) {
  for (std::size_t at = text.find(placeholder); at != std::string::npos;
       at = text.find(placeholder, at + value.size())) {
    text.replace(at, placeholder.size(), value);
  }
  return text;
}

/// `page_template` with each placeholder replaced by its value, in one pass (so that a value
/// that happens to contain a placeholder's name is left as it is).
std::string fill_template(const std::vector<std::pair<std::string, std::string>>& values) {
  const std::string text = page_template;
  std::string filled;
  for (std::size_t at = 0; at < text.size();) {
    const auto match = std::find_if(values.begin(), values.end(), [&](const auto& value) {
      return text.compare(at, value.first.size(), value.first) == 0;
    });
    if (match == values.end()) {
      filled += text[at++];
    } else {
      filled += match->second;
      at += match->first.size();
    }
  }
  return filled;
}

/// {"frames": [...], "variants": [...]} with every '<' written as \u003c so that no string in
/// it can end the <script> element it sits in.
std::string page_data_json(const ViewerPage& page) {
  nlohmann::json frames = nlohmann::json::array();
  for (const ViewerFrame& frame : page.frames) {
    nlohmann::json row = {{"frame", frame.index.frame},
                          {"step", frame.index.step},
                          {"time", frame.index.time},
                          {"energy", frame.energy},  // a non-finite energy becomes null
                          {"contacts", frame.contacts},
                          {"file", frame.index.file}};
    if (page.events) {
      row["events"] = {{"touch_begin", frame.events.touch_begin}, {"touch_end", frame.events.touch_end},
                       {"hit", frame.events.hit}, {"sensor_begin", frame.events.sensor_begin},
                       {"sensor_end", frame.events.sensor_end}};
    }
    frames.push_back(row);
  }
  nlohmann::json variants = nlohmann::json::array();
  for (const ViewerVariant& variant : page.variants) {
    variants.push_back({{"label", variant.label}, {"directory", variant.directory}});
  }
  const nlohmann::json data = {{"frames", frames}, {"variants", variants}};
  return replace_all(data.dump(), "<", "\\u003c");
}

}  // namespace

std::filesystem::path html_viewer_path(const std::filesystem::path& directory,
                                       const std::string& scene) {
  return directory / (scene + ".html");
}

std::string html_viewer_page(const ViewerPage& page) {
  return fill_template({{"@TITLE@", golden::escape_html(page.title)},
                        {"@DETAILS@", golden::escape_html(page.details)},
                        {"@WIDTH@", std::to_string(page.width)},
                        {"@HEIGHT@", std::to_string(page.height)},
                        {"@DATA@", page_data_json(page)}});
}

void write_html_viewer(const std::filesystem::path& path, const ViewerPage& page) {
  const std::string html = html_viewer_page(page);
  image::write_file_atomically(path, std::vector<std::uint8_t>(html.begin(), html.end()));
}

}  // namespace impulse2d::demos
