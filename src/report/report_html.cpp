// report.html: the method comparison as one self-contained page. The tables are HTML (readable
// without JavaScript); the plots are Chart.js and the 3D view three.js, both inlined from the
// pinned npm packages (report_assets.hpp), three.js through an import map of data: URLs. The
// page's own script only feeds them the data.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <locale>
#include <ostream>
#include <string>

#include "report/report_assets.hpp"
#include "towgeom/error.hpp"
#include "towgeom/method_comparison.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Json = nlohmann::ordered_json;

std::string base64(const void* data, std::size_t size)
{
    static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const auto* b = static_cast<const unsigned char*>(data);
    std::string out;
    out.reserve((size + 2) / 3 * 4);
    for (std::size_t i = 0; i < size; i += 3) {
        const std::uint32_t n = (std::uint32_t(b[i]) << 16) | (i + 1 < size ? std::uint32_t(b[i + 1]) << 8 : 0u) |
                                (i + 2 < size ? std::uint32_t(b[i + 2]) : 0u);
        out += kDigits[(n >> 18) & 63];
        out += kDigits[(n >> 12) & 63];
        out += i + 1 < size ? kDigits[(n >> 6) & 63] : '=';
        out += i + 2 < size ? kDigits[n & 63] : '=';
    }
    return out;
}

std::string escapeHtml(const std::string& s)
{
    std::string out;
    for (char c : s) switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    return out;
}

/// JSON text safe inside a <script> element: <, > and & as \u escapes (no "</script>", no
/// "<!--" can appear, whatever the tows are called).
std::string scriptJson(const Json& j)
{
    const std::string s = j.dump(-1, ' ', false, Json::error_handler_t::replace);
    std::string out;
    out.reserve(s.size());
    for (const char c : s) {
        if (c == '<') out += "\\u003c";
        else if (c == '>') out += "\\u003e";
        else if (c == '&') out += "\\u0026";
        else out += c;
    }
    return out;
}

/// @p x with @p digits significant digits (or the shortest exact text for digits 0), whatever
/// the stream's locale; "-" when not finite.
std::string number(double x, int digits = 6)
{
    if (!std::isfinite(x)) return "-";
    char text[64];
    const auto r = digits > 0 ? std::to_chars(text, text + sizeof text, x, std::chars_format::general, digits)
                              : std::to_chars(text, text + sizeof text, x);
    return std::string(text, r.ptr);
}

/// One tow's mesh for the 3D view: its nodes (float32 x, y, z), triangles (uint32, into those
/// nodes) and each triangle's region (int32), base64.
Json viewTow(const TextileMesh& mesh, std::size_t t)
{
    const TowMesh& m = mesh.tows[t];
    std::vector<std::uint32_t> local(mesh.nodes.size(), UINT32_MAX);
    std::vector<float> xyz;
    std::vector<std::uint32_t> triangles;
    std::vector<std::int32_t> regions;
    for (std::size_t k = 0; k < m.triangles.size(); ++k) {
        for (std::size_t n : m.triangles[k]) {
            if (local[n] == UINT32_MAX) {
                local[n] = static_cast<std::uint32_t>(xyz.size() / 3);
                const Point3& p = mesh.nodes[n];
                xyz.insert(xyz.end(), {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
            }
            triangles.push_back(local[n]);
        }
        regions.push_back(static_cast<std::int32_t>(k < m.region.size() ? m.region[k] : -1));
    }
    return {{"name", m.name},
            {"nodes", base64(xyz.data(), xyz.size() * sizeof(float))},
            {"triangles", base64(triangles.data(), triangles.size() * sizeof(std::uint32_t))},
            {"regions", base64(regions.data(), regions.size() * sizeof(std::int32_t))}};
}

Json dataOf(const MethodComparison& c, const TextileMesh& view)
{
    Json j;
    j["tows"] = c.towNames;
    j["stations"] = c.stations;
    j["sectionAreaBefore"] = c.sectionAreaBefore;
    Json methods = Json::array();
    for (const MethodFigures& m : c.methods) {
        Json e;
        e["name"] = resolutionMethodName(m.method);
        Json change = Json::array(), areas = Json::array();
        for (const TowMethodFigures& t : m.tows) {
            change.push_back(t.volumeChangePercent());
            areas.push_back(t.sectionArea);
        }
        e["volumeChangePercent"] = std::move(change);
        e["sectionArea"] = std::move(areas);
        e["angleHistogram"] = m.quality.histogram;
        methods.push_back(std::move(e));
    }
    j["methods"] = std::move(methods);
    j["viewMethod"] = resolutionMethodName(c.methods.front().method);
    Json towsView = Json::array();
    for (std::size_t t = 0; t < view.tows.size(); ++t) towsView.push_back(viewTow(view, t));
    j["view"] = std::move(towsView);
    j["regionCount"] = view.regions.size();
    return j;
}

const char* kStyle = R"(
body{font-family:system-ui,sans-serif;margin:1.5em auto;max-width:1200px;color:#222;padding:0 1em}
h1{font-size:1.6em}h2{font-size:1.25em;margin-top:1.6em;border-bottom:1px solid #ccc}
table{border-collapse:collapse;font-size:.88em;margin:.5em 0}th,td{border:1px solid #ccc;padding:.2em .5em;text-align:right}
th{background:#f0f0f0}td:first-child,th:first-child{text-align:left}.loss{color:#a40000}.chart{position:relative;height:340px}
#view{width:100%;height:520px;border:1px solid #ccc;background:#fafafa}.controls label{margin-right:1em;white-space:nowrap}
.note{color:#555;font-size:.9em}
)";

/// The page's own script: the plots (Chart.js, global Chart).
const char* kChartsScript = R"(
(function () {
  const data = JSON.parse(document.getElementById('report-data').textContent);
  const colours = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e'];
  let drawn = 0;
  new Chart(document.getElementById('volume-chart'), {
    type: 'bar',
    data: { labels: data.tows, datasets: data.methods.map((m, i) => ({ label: m.name, data: m.volumeChangePercent, backgroundColor: colours[i % colours.length] })) },
    options: { maintainAspectRatio: false, animation: false, scales: { y: { title: { display: true, text: 'volume change (%)' } } } }
  });
  ++drawn;
  const bins = data.methods[0].angleHistogram.map((_, i) => (5 * i) + '-' + (5 * i + 5));
  new Chart(document.getElementById('quality-chart'), {
    type: 'bar',
    data: { labels: bins, datasets: data.methods.map((m, i) => ({ label: m.name, data: m.angleHistogram, backgroundColor: colours[i % colours.length] })) },
    options: { maintainAspectRatio: false, animation: false, scales: { x: { title: { display: true, text: 'smallest angle of a triangle (degrees)' } }, y: { type: 'logarithmic', title: { display: true, text: 'triangles' } } } }
  });
  ++drawn;
  const select = document.getElementById('section-tow');
  data.tows.forEach((name, t) => select.add(new Option(name, t)));
  const sectionChart = new Chart(document.getElementById('section-chart'), {
    type: 'line', data: { datasets: [] },
    options: { maintainAspectRatio: false, animation: false, parsing: false,
      scales: { x: { type: 'linear', title: { display: true, text: 'length along the tow' } }, y: { title: { display: true, text: 'section area' } } } }
  });
  function showSections(t) {
    const xs = data.stations[t];
    const series = (ys) => xs.map((x, i) => ({ x: x, y: ys[i] }));
    sectionChart.data.datasets = [{ label: 'before', data: series(data.sectionAreaBefore[t]), borderColor: '#000', borderDash: [4, 3], pointRadius: 0 }]
      .concat(data.methods.map((m, i) => ({ label: m.name, data: series(m.sectionArea[t]), borderColor: colours[i % colours.length], pointRadius: 0 })));
    sectionChart.update();
  }
  // The tow that changed most under the first method is shown first.
  let worst = 0;
  data.methods[0].volumeChangePercent.forEach((c, t) => { if (c < data.methods[0].volumeChangePercent[worst]) worst = t; });
  select.value = worst;
  select.addEventListener('change', () => showSections(Number(select.value)));
  showSections(worst);
  ++drawn;
  document.body.dataset.charts = String(drawn);
  // How much of each plot shows data: pixels in the methods' colours (axes, grid and text are
  // grey or black; the legend's swatches are a few hundred pixels), for a check that none is blank.
  const rgb = colours.map((c) => [1, 3, 5].map((k) => parseInt(c.substr(k, 2), 16)));
  document.body.dataset.chartPixels = ['volume-chart', 'section-chart', 'quality-chart'].map((id) => {
    const canvas = document.getElementById(id);
    const pixels = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
    let data = 0;
    for (let i = 0; i < pixels.length; i += 4)
      if (pixels[i + 3] > 200 && rgb.some((c) => Math.abs(pixels[i] - c[0]) + Math.abs(pixels[i + 1] - c[1]) + Math.abs(pixels[i + 2] - c[2]) < 60)) ++data;
    return (data / (canvas.width * canvas.height)).toFixed(4);
  }).join(',');
})();
)";

/// The page's own module: the 3D view (three.js and its OrbitControls through the import map).
const char* kViewScript = R"(
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
const data = JSON.parse(document.getElementById('report-data').textContent);
const box = document.getElementById('view');
const decode = (text, Type) => { const b = atob(text); const u = new Uint8Array(b.length); for (let i = 0; i < b.length; ++i) u[i] = b.charCodeAt(i); return new Type(u.buffer); };
let renderer;
try { renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true }); }
catch (e) { box.textContent = 'This browser cannot show WebGL: ' + e.message; document.body.dataset.view = 'no-webgl'; }
if (renderer) {
  renderer.setSize(box.clientWidth, box.clientHeight);
  box.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xfafafa);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 2.0));
  const sun = new THREE.DirectionalLight(0xffffff, 1.5); sun.position.set(1, 2, 3); scene.add(sun);
  const towColour = (t) => new THREE.Color().setHSL((t * 0.618034) % 1, 0.55, 0.55);
  const regionColour = (r) => r < 0 ? new THREE.Color(0xbbbbbb) : new THREE.Color().setHSL((r * 0.618034 + 0.3) % 1, 0.8, 0.45);
  const meshes = [];
  const bounds = new THREE.Box3();
  data.view.forEach((tow, t) => {
    const xyz = decode(tow.nodes, Float32Array), tri = decode(tow.triangles, Uint32Array), region = decode(tow.regions, Int32Array);
    const positions = new Float32Array(tri.length * 3), colours = new Float32Array(tri.length * 3);
    for (let k = 0; k < tri.length; ++k) for (let c = 0; c < 3; ++c) positions[3 * k + c] = xyz[3 * tri[k] + c];
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
    geometry.computeVertexNormals();
    geometry.computeBoundingBox();
    if (tri.length) bounds.union(geometry.boundingBox);
    const mesh = new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({ vertexColors: true, side: THREE.DoubleSide, roughness: 0.7 }));
    mesh.userData = { tow: t, region: region };
    scene.add(mesh);
    meshes.push(mesh);
  });
  function colourBy(mode) {
    for (const mesh of meshes) {
      const colours = mesh.geometry.attributes.color;
      const region = mesh.userData.region;
      for (let k = 0; k < region.length; ++k) {
        const c = mode === 'region' ? regionColour(region[k]) : towColour(mesh.userData.tow);
        for (let v = 0; v < 3; ++v) colours.setXYZ(3 * k + v, c.r, c.g, c.b);
      }
      colours.needsUpdate = true;
    }
    render();
  }
  const camera = new THREE.PerspectiveCamera(35, box.clientWidth / box.clientHeight, 1e-3, 1e3);
  const sphere = bounds.getBoundingSphere(new THREE.Sphere());
  const r = sphere.radius > 0 ? sphere.radius : 1;
  camera.near = r / 100; camera.far = r * 100;
  camera.position.copy(sphere.center).add(new THREE.Vector3(0.8 * r, -2.2 * r, 1.6 * r));
  camera.up.set(0, 0, 1);
  camera.updateProjectionMatrix();
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(sphere.center);
  controls.update();
  function render() { renderer.render(scene, camera); }
  controls.addEventListener('change', render);
  const toggles = document.getElementById('view-tows');
  meshes.forEach((mesh, t) => {
    const label = document.createElement('label');
    const tick = document.createElement('input');
    tick.type = 'checkbox'; tick.checked = true;
    tick.addEventListener('change', () => { mesh.visible = tick.checked; render(); });
    label.append(tick, ' ' + data.view[t].name);
    toggles.appendChild(label);
  });
  document.querySelectorAll('input[name=colour]').forEach((radio) => radio.addEventListener('change', () => colourBy(radio.value)));
  colourBy('tow');
  // How much of the view the tows cover (for a check that the view is not blank).
  const gl = renderer.getContext();
  const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight, pixels = new Uint8Array(4 * w * h);
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  let covered = 0;
  for (let i = 0; i < pixels.length; i += 4) if (Math.abs(pixels[i] - 250) + Math.abs(pixels[i + 1] - 250) + Math.abs(pixels[i + 2] - 250) > 24) ++covered;
  document.body.dataset.view = String(meshes.length);
  document.body.dataset.viewCovered = (covered / (w * h)).toFixed(3);
}
)";

void writeTowTable(const MethodComparison& c, std::ostream& out)
{
    out << "<div style=\"overflow-x:auto\"><table><tr><th>tow</th>";
    for (const MethodFigures& m : c.methods)
        out << "<th colspan=\"" << (m.method == ResolutionMethod::Shrink ? 6 : 5) << "\">" << resolutionMethodName(m.method) << "</th>";
    out << "</tr><tr><th></th>";
    for (const MethodFigures& m : c.methods)
        out << "<th>role</th><th>volume before</th><th>volume after</th><th>change %</th><th>area</th>"
            << (m.method == ResolutionMethod::Shrink ? "<th>largest section change</th>" : "");
    out << "</tr>\n";
    for (std::size_t t = 0; t < c.towNames.size(); ++t) {
        out << "<tr><td>" << escapeHtml(c.towNames[t]) << "</td>";
        for (const MethodFigures& m : c.methods) {
            const TowMethodFigures& f = m.tows[t];
            const double change = f.volumeChangePercent();
            out << "<td>" << f.role << "</td><td>" << number(f.volumeBefore) << "</td><td>" << number(f.volumeAfter) << "</td><td"
                << (change < -1e-9 ? " class=\"loss\"" : "") << ">" << number(change, 3) << "</td><td>" << number(f.area) << "</td>";
            if (m.method == ResolutionMethod::Shrink) out << "<td>" << number(f.largestSectionChange, 3) << "</td>";
        }
        out << "</tr>\n";
    }
    out << "</table></div>\n";
}

void writeSummary(const MethodComparison& c, std::ostream& out)
{
    out << "<table><tr><th>method</th><th>regions (shared surfaces)</th><th>unresolved pairs</th><th>volume lost, all tows</th>"
           "<th>largest loss of a tow</th><th>triangles</th><th>smallest angle</th><th>time (ms)</th></tr>\n";
    for (const MethodFigures& m : c.methods) {
        double total = 0.0, largest = 0.0;
        for (const TowMethodFigures& f : m.tows) {
            total += f.volumeBefore - f.volumeAfter;
            largest = std::max(largest, f.volumeBefore - f.volumeAfter);
        }
        out << "<tr><td>" << resolutionMethodName(m.method) << "</td><td>" << m.regions << "</td><td>" << m.unresolvedPairs << "</td><td>"
            << number(total) << "</td><td>" << number(largest) << "</td><td>" << m.quality.triangles << "</td><td>"
            << number(m.quality.minAngle, 3) << "</td><td>" << number(m.milliseconds, 4) << "</td></tr>\n";
    }
    out << "</table>\n";
}

/// The classic "C" locale on a stream while it lives (integers without digit grouping), the
/// caller's restored after.
class ClassicLocale {
public:
    explicit ClassicLocale(std::ostream& out) : out_(out), saved_(out.imbue(std::locale::classic())) {}
    ~ClassicLocale() { out_.imbue(saved_); }
    ClassicLocale(const ClassicLocale&) = delete;
    ClassicLocale& operator=(const ClassicLocale&) = delete;

private:
    std::ostream& out_;
    std::locale saved_;
};

}  // namespace

void writeReportHtml(const MethodComparison& c, const TextileMesh& view, std::ostream& out)
{
    if (view.tows.size() != c.towNames.size())
        throw Error(ErrorCode::InvalidArgument, "the 3D view's mesh has " + std::to_string(view.tows.size()) + " tows, the comparison " +
                                                    std::to_string(c.towNames.size()));
    if (c.methods.empty()) throw Error(ErrorCode::InvalidArgument, "the comparison has no method");
    const ClassicLocale classic(out);
    for (const MethodFigures& m : c.methods)
        if (m.tows.size() != c.towNames.size()) throw Error(ErrorCode::InvalidArgument, "a method's figures are not of the comparison's tows");
    const Json imports = {{"imports",
                           {{"three", "data:text/javascript;base64," + base64(detail::kThreeJs, detail::kThreeJsSize)},
                            {"three/addons/controls/OrbitControls.js",
                             "data:text/javascript;base64," + base64(detail::kOrbitControlsJs, detail::kOrbitControlsJsSize)}}}};
    out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>towgeom: resolution methods compared</title>\n<style>"
        << kStyle << "</style>\n"
        << "<!-- Chart.js 4.5.1 (MIT, Chart.js Contributors; bundles @kurkle/color, MIT) and three.js 0.169.0 (MIT, three.js "
           "authors), inlined verbatim from their npm packages -->\n"
        << "<script>(function () { const count = () => { document.documentElement.dataset.errors = String(Number(document.documentElement.dataset.errors || 0) + 1); };"
           " window.addEventListener('error', count); window.addEventListener('unhandledrejection', count);"
           " const error = console.error; console.error = function () { count(); error.apply(console, arguments); }; })();</script>\n"
        << "<script>" << detail::asset(detail::kChartJs, detail::kChartJsSize) << "</script>\n"
        << "<script type=\"importmap\">" << scriptJson(imports) << "</script>\n</head><body>\n";
    out << "<h1>Resolution methods compared</h1>\n<p class=\"note\">" << c.towNames.size() << " tows, " << c.loops.size()
        << " intersection loops (intersection " << number(c.intersectMilliseconds, 4) << " ms, meshing " << number(c.meshMilliseconds, 4)
        << " ms). <b>connect</b>: the lower-ranked tow of a pair gives way to the higher, which keeps its surface; <b>symmetric</b>: both "
           "give way to the mid-surface between them; <b>shrink</b>: the tows' sections are scaled down until no pair interpenetrates "
           "(no shared surface).</p>\n";
    out << "<h2>Summary</h2>\n";
    writeSummary(c, out);
    out << "<h2>Volume change per tow</h2>\n<div class=\"chart\"><canvas id=\"volume-chart\"></canvas></div>\n";
    out << "<h2>Section area along a tow</h2>\n<p>Tow <select id=\"section-tow\"></select> <span class=\"note\">(each input section's "
           "plane cuts the tow's mesh before and after; the tow that lost most under "
        << resolutionMethodName(c.methods.front().method) << " first)</span></p>\n<div class=\"chart\"><canvas id=\"section-chart\"></canvas></div>\n";
    out << "<h2>Tows</h2>\n";
    writeTowTable(c, out);
    out << "<h2>3D view (" << resolutionMethodName(c.methods.front().method) << ")</h2>\n<p class=\"controls\">Colour by "
        << "<label><input type=\"radio\" name=\"colour\" value=\"tow\" checked> tow</label><label><input type=\"radio\" name=\"colour\" "
           "value=\"region\"> region (shared surfaces; grey outside)</label><br><span id=\"view-tows\"></span></p>\n<div id=\"view\"></div>\n"
           "<p class=\"note\">Drag to rotate, scroll to zoom, right-drag to pan.</p>\n";
    out << "<h2>Mesh quality</h2>\n<div class=\"chart\"><canvas id=\"quality-chart\"></canvas></div>\n";
    out << "<h2>Connected regions (" << resolutionMethodName(c.methods.front().method) << ")</h2>\n<table><tr><th>region</th><th>primary</th>"
           "<th>secondary</th><th>surface</th><th>triangles</th><th>area</th><th>overlap volume</th></tr>\n";
    for (std::size_t g = 0; g < c.regions.size(); ++g) {
        const RegionRow& r = c.regions[g];
        out << "<tr><td>" << g << "</td><td>" << escapeHtml(c.towNames.at(r.primary)) << "</td><td>" << escapeHtml(c.towNames.at(r.secondary))
            << "</td><td>" << (r.surface == SharedSurface::Middle ? "middle" : "primary") << "</td><td>" << r.triangles << "</td><td>"
            << number(r.area) << "</td><td>" << number(r.volumeRemoved) << "</td></tr>\n";
    }
    out << "</table>\n<h2>Intersection loops</h2>\n<table><tr><th>loop</th><th>tow A</th><th>tow B</th><th>closed</th><th>length</th>"
           "<th>area on A</th><th>area on B</th></tr>\n";
    for (std::size_t k = 0; k < c.loops.size(); ++k) {
        const LoopRow& l = c.loops[k];
        out << "<tr><td>" << k << "</td><td>" << escapeHtml(c.towNames.at(l.towA)) << "</td><td>" << escapeHtml(c.towNames.at(l.towB))
            << "</td><td>" << (l.closed ? "yes" : "no") << "</td><td>" << number(l.length) << "</td><td>" << number(l.areaA) << "</td><td>"
            << number(l.areaB) << "</td></tr>\n";
    }
    out << "</table>\n<h2>Licences</h2>\n<details><summary>The page inlines Chart.js 4.5.1 (with @kurkle/color) and three.js "
           "0.169.0 with its OrbitControls, verbatim from their npm packages, under these licences.</summary>\n";
    for (const auto& [name, text] : {std::pair{"Chart.js", detail::asset(detail::kChartJsLicence, detail::kChartJsLicenceSize)},
                                      std::pair{"@kurkle/color", detail::asset(detail::kKurkleColorLicence, detail::kKurkleColorLicenceSize)},
                                      std::pair{"three.js", detail::asset(detail::kThreeJsLicence, detail::kThreeJsLicenceSize)}})
        out << "<h3>" << name << "</h3><pre>" << escapeHtml(std::string(text)) << "</pre>\n";
    out << "</details>\n<script type=\"application/json\" id=\"report-data\">" << scriptJson(dataOf(c, view)) << "</script>\n";
    out << "<script>" << kChartsScript << "</script>\n<script type=\"module\">" << kViewScript << "</script>\n"
        << "<script>window.addEventListener('load', () => { if (!document.body.dataset.view) document.getElementById('view').textContent = "
           "'The 3D view could not be loaded: it needs a browser with import maps and WebGL (Chrome 89+, Firefox 108+, Safari 16.4+).'; });"
           "</script>\n</body></html>\n";
    if (!out) throw Error(ErrorCode::WriteFailed, "could not write the report");
}

void writeReportCsv(const MethodComparison& c, std::ostream& out)
{
    const ClassicLocale classic(out);
    out << "tow,method,role,volume_before,volume_after,volume_change_percent,area,triangles,largest_section_change\n";
    for (const MethodFigures& m : c.methods)
        for (std::size_t t = 0; t < c.towNames.size(); ++t) {
            const TowMethodFigures& f = m.tows[t];
            std::string name = c.towNames[t];
            if (name.find_first_of(",\"\n") != std::string::npos) {
                std::string quoted = "\"";
                for (char ch : name) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
                name = quoted + "\"";
            }
            out << name << ',' << resolutionMethodName(m.method) << ',' << f.role << ',' << number(f.volumeBefore, 0) << ','
                << number(f.volumeAfter, 0) << ',' << number(f.volumeChangePercent(), 0) << ',' << number(f.area, 0) << ','
                << std::to_string(f.triangles) << ',' << number(f.largestSectionChange, 0) << '\n';
        }
    if (!out) throw Error(ErrorCode::WriteFailed, "could not write the CSV report");
}

TOWGEOM_END_NAMESPACE
