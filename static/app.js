// PMA calculator page. Every number shown comes from the HTTP API; this script only converts
// units, sends requests and draws the answers. plotly.js (4.8 MB) loads asynchronously while
// the first requests are under way; only drawing waits for it.
/* global Plotly */

const API = "api/v1/";
const DEBOUNCE_MS = 150;
const HYSTERESIS_POINTS = 201;
const OTHER_PRESSURES_KPA = [100, 300, 500];
const PRESSURE_SWEEP = { minKpa: 50, maxKpa: 600, points: 60 };
const STRAND_SWEEP_MIN = 2;
const STRAND_SWEEP_MAX = 400;

// Display unit -> SI. Division by a power of ten keeps 0.25 mm exactly 0.00025 m.
const TO_SI = {
  mm: (v) => v / 1e3,
  m: (v) => v,
  GPa: (v) => v * 1e9,
  MPa: (v) => v * 1e6,
  kPa: (v) => v * 1e3,
  bar: (v) => v * 1e5,
  one: (v) => v,
};

// Form input id -> JSON field (SI) and the input's display unit.
const FIELDS = {
  Do: { json: "theoretical_diameter_m", unit: "mm" },
  b: { json: "strand_length_m", unit: "m" },
  n: { json: "turns", unit: "one" },
  Ds: { json: "strand_diameter_m", unit: "mm" },
  N: { json: "strand_count", unit: "one" },
  S: { json: "parallel_strands", unit: "one" },
  E: { json: "youngs_modulus_pa", unit: "GPa" },
  nu: { json: "poisson_ratio", unit: "one" },
  su: { json: "tensile_strength_pa", unit: "MPa" },
  fs: { json: "friction_coefficient", unit: "one" },
  sf: { json: "safety_factor", unit: "one" },
  P: { json: "pressure_pa", unit: "pressure" },
  Sscale: { json: "s_scale", unit: "one", optional: true },
};
const INPUT_FOR_JSON = Object.fromEntries(Object.entries(FIELDS).map(([id, f]) => [f.json, id]));
const GEOMETRY_INPUTS = { diameter: ["Do"], turns: ["n"] };

const PLOT_CONFIG = (name) => ({
  responsive: true,
  displaylogo: false,
  modeBarButtonsToRemove: ["select2d", "lasso2d"],
  toImageButtonOptions: { format: "png", filename: name, scale: 2 },
});
const COLORS = { design: "#0b4f8a", measured: "#b3261e", marker: "#e8710a", static: "#333333" };
const OTHER_COLORS = ["#2e8b57", "#8c6bb1", "#b8860b", "#6a8fb3"];

const form = document.getElementById("design-form");
const results = document.getElementById("results");
const statusLine = document.getElementById("status");
const timings = { firstPlotsMs: null, lastUpdateMs: null, updates: 0 };
window.__pmaTimings = timings;

const plotlyLoaded = new Promise((resolve, reject) => {
  if (window.Plotly) return resolve();
  const script = document.getElementById("plotly-js");
  script.addEventListener("load", resolve);
  script.addEventListener("error", () => reject(new Error("plotly.js could not be loaded.")));
});

let materials = [];
let reference = null;
let controller = null;
let debounceTimer = 0;

// ---------------------------------------------------------------- API access

class ApiError extends Error {
  constructor(status, detail) {
    super(typeof detail === "string" ? detail : `The API answered ${status}.`);
    this.status = status;
    this.detail = detail;
  }
}

async function api(path, body, signal) {
  const headers = { "Content-Type": "application/json" };
  const init = body === undefined ? { signal } : { method: "POST", headers, body: JSON.stringify(body), signal };
  const response = await fetch(API + path, init);
  const data = await response.json().catch(() => null);
  if (!response.ok) throw new ApiError(response.status, data?.detail);
  return data;
}

/** The 422 detail as [{field, msg}] (field: the JSON name, or null for the whole body). */
function problems(error) {
  if (!(error instanceof ApiError) || !Array.isArray(error.detail)) {
    return [{ field: null, msg: error.message || String(error) }];
  }
  return error.detail.map((item) => {
    const loc = Array.isArray(item.loc) ? item.loc : [];
    const last = loc.length > 1 ? loc[loc.length - 1] : null;
    const field = typeof last === "string" ? last : null;
    // The input beside which the message appears already names the field.
    const msg = String(item.msg);
    return { field, msg: field && msg.startsWith(`${field}: `) ? msg.slice(field.length + 2) : msg };
  });
}

// ---------------------------------------------------------------- the form

function geometryMode() {
  return form.elements.geometry.value;
}

function readInput(id) {
  const input = document.getElementById(id);
  const text = input.value.trim();
  const number = Number(text);
  if (input.validity.badInput || !Number.isFinite(number)) return { error: "Enter a number." };
  if (text === "") return FIELDS[id].optional ? { value: undefined } : { error: "Enter a value." };
  const unit = FIELDS[id].unit === "pressure" ? form.elements.Punit.value : FIELDS[id].unit;
  return { value: TO_SI[unit](number) };
}

function activeInputs() {
  const hidden = new Set(Object.values(GEOMETRY_INPUTS).flat());
  GEOMETRY_INPUTS[geometryMode()].forEach((id) => hidden.delete(id));
  return Object.keys(FIELDS).filter((id) => !hidden.has(id));
}

/** The design in SI, keyed by JSON field, and local errors by input (empty or not a number). */
function readForm() {
  const values = {};
  const errors = new Map();
  for (const id of activeInputs()) {
    const { value, error } = readInput(id);
    if (error) errors.set(id, [error]);
    else if (value !== undefined) values[FIELDS[id].json] = value;
  }
  return { values, errors };
}

function pick(values, names) {
  return Object.fromEntries(names.filter((name) => name in values).map((name) => [name, values[name]]));
}

function geometry(values) {
  return geometryMode() === "turns"
    ? pick(values, ["strand_length_m", "turns"])
    : pick(values, ["theoretical_diameter_m", "strand_length_m"]);
}

// ---------------------------------------------------------------- requests

function requestPlan(v) {
  const hysteresisBase = {
    ...geometry(v),
    ...pick(v, ["strand_diameter_m", "strand_count", "friction_coefficient", "youngs_modulus_pa", "poisson_ratio"]),
    points: HYSTERESIS_POINTS,
  };
  const others = OTHER_PRESSURES_KPA.map((kpa) => kpa * 1e3).filter((pa) => pa !== v.pressure_pa);
  return {
    design: {
      path: "design",
      body: {
        ...geometry(v),
        ...pick(v, [
          "strand_diameter_m", "strand_count", "parallel_strands", "pressure_pa", "youngs_modulus_pa",
          "poisson_ratio", "tensile_strength_pa", "friction_coefficient", "safety_factor", "s_scale",
        ]),
      },
    },
    hysteresis: {
      path: "hysteresis",
      body: { ...hysteresisBase, ...pick(v, ["pressure_pa", "s_scale"]) },
    },
    ...(others.length ? {
      hysteresisOthers: { path: "sweeps/hysteresis", body: { ...hysteresisBase, pressures_pa: others } },
    } : {}),
    strandSweep: {
      path: "sweeps/strand-count",
      body: {
        ...geometry(v),
        ...pick(v, ["strand_diameter_m", "parallel_strands"]),
        strand_count_min: STRAND_SWEEP_MIN,
        strand_count_max: Math.max(STRAND_SWEEP_MAX, 2 * Math.round(v.strand_count)),
      },
    },
    pressureSweep: {
      path: "sweeps/pressure",
      body: {
        ...geometry(v),
        ...pick(v, ["strand_diameter_m", "tensile_strength_pa", "safety_factor", "youngs_modulus_pa", "poisson_ratio"]),
        pressure_min_pa: PRESSURE_SWEEP.minKpa * 1e3,
        pressure_max_pa: Math.max(PRESSURE_SWEEP.maxKpa * 1e3, 1.5 * v.pressure_pa),
        points: PRESSURE_SWEEP.points,
      },
    },
  };
}

/** Send every request of the plan at once; settle to {key: {ok, data} | {ok: false, error}}. */
async function runPlan(plan, signal) {
  const keys = Object.keys(plan);
  const settled = await Promise.allSettled(keys.map((key) => api(plan[key].path, plan[key].body, signal)));
  return Object.fromEntries(keys.map((key, i) => [key, settled[i].status === "fulfilled"
    ? { ok: true, data: settled[i].value }
    : { ok: false, error: settled[i].reason }]));
}

// ---------------------------------------------------------------- errors beside fields

function setFieldError(id, message) {
  const input = document.getElementById(id);
  const errorId = `${id}-error`;
  let error = document.getElementById(errorId);
  if (!error) {
    error = document.createElement("p");
    error.id = errorId;
    error.className = "field-error";
    input.closest(".field").append(error);
  }
  error.textContent = message;
  input.setAttribute("aria-invalid", "true");
  const hint = document.getElementById(`${id}-hint`);
  input.setAttribute("aria-describedby", [hint?.id, errorId].filter(Boolean).join(" "));
}

function clearFieldErrors() {
  for (const error of form.querySelectorAll(".field-error")) {
    const input = error.closest(".field").querySelector("input");
    input.removeAttribute("aria-invalid");
    const hint = document.getElementById(`${input.id}-hint`);
    if (hint) input.setAttribute("aria-describedby", hint.id);
    else input.removeAttribute("aria-describedby");
    error.remove();
  }
}

/** Replace the errors shown: messages beside inputs (Map id -> [msg]) and for the whole form. */
function showErrors(byInput, formMessages = []) {
  clearFieldErrors();
  byInput.forEach((messages, id) => setFieldError(id, [...new Set(messages)].join(" ")));
  const box = document.getElementById("form-error");
  box.textContent = [...new Set(formMessages)].join(" ");
  box.hidden = formMessages.length === 0;
}

/**
 * Sort the failed requests' messages: beside the input a field's value came from; else, for
 * the design, on the whole form; else (a value the page chose: a sweep bound, another
 * pressure) beside the plot that needed the request.
 */
function routeErrors(plan, outcomes, values) {
  const byInput = new Map();
  const general = [];
  const byRequest = {};
  for (const [key, outcome] of Object.entries(outcomes)) {
    if (outcome.ok) continue;
    byRequest[key] = [];
    for (const { field, msg } of problems(outcome.error)) {
      const input = INPUT_FOR_JSON[field];
      if (input && plan[key].body[field] === values[field]) {
        byInput.set(input, [...(byInput.get(input) ?? []), msg]);
      } else if (key === "design") {
        general.push(msg);
      } else {
        byRequest[key].push(field ? `${field}: ${msg}` : msg);
      }
    }
  }
  return { byInput, general, byRequest };
}

// ---------------------------------------------------------------- results

const fmt = (value, digits) => new Intl.NumberFormat("en", { maximumSignificantDigits: digits }).format(value);
const deg = (value) => `${value.toFixed(1)}°`;
const mm = (metres) => `${(metres * 1e3).toFixed(1)} mm`;

function text(id, value) {
  document.getElementById(id).textContent = value;
}

function verdict(id, needed, strandCount) {
  const cell = document.getElementById(id);
  const pass = strandCount >= needed;
  cell.textContent = pass ? "PASS" : "FAIL";
  cell.className = pass ? "pass" : "fail";
}

function renderResults(d, strandCount) {
  const f = d.failure_strand_count;
  text("r-size", `${mm(d.theoretical_diameter_m)} / ${d.turns === null ? "–" : d.turns.toFixed(2)}`);
  text("r-theta-min", deg(d.min_braid_angle_deg));
  text("r-jamming", deg(d.jamming_angle_deg));
  text("r-theta-max", deg(d.max_braid_angle_deg));
  text("r-contraction", `${(d.max_contraction * 100).toFixed(1)} %`);
  text("r-lengths", d.max_length_m === null ? "needs b and n" : `${mm(d.max_length_m)} / ${mm(d.min_length_m)}`);
  text("r-stroke", d.stroke_m === null ? "needs b and n" : mm(d.stroke_m));
  text("r-force", `${fmt(d.peak_static_force_n, 4)} N`);
  text("r-gap", `${fmt(d.max_gap_area_m2 * 1e6, 3)} mm²`);
  text("r-sscale", fmt(d.s_scale, 3));
  text("r-fail-full-label", `Full contraction (${deg(f.braid_angle_deg)})`);
  text("r-fail-worst-label", `Worst case (${deg(f.worst_case_braid_angle_deg)})`);
  text("r-fail-full", `${f.min_strand_count} (${f.min_strand_count_exact.toFixed(1)})`);
  text("r-fail-worst", `${f.worst_case_min_strand_count} (${f.worst_case_min_strand_count_exact.toFixed(1)})`);
  for (const cell of results.querySelectorAll(".design-n")) cell.textContent = String(strandCount);
  verdict("r-fail-full-verdict", f.min_strand_count, strandCount);
  verdict("r-fail-worst-verdict", f.worst_case_min_strand_count, strandCount);
  renderWarnings(d.warnings);
}

function renderWarnings(warnings) {
  const list = document.getElementById("warnings");
  const items = warnings.map((w) => {
    const item = document.createElement("li");
    item.textContent = w.message;
    item.dataset.code = w.code;
    return item;
  });
  if (items.length === 0) {
    const none = document.createElement("li");
    none.className = "none";
    none.textContent = "None.";
    items.push(none);
  }
  list.replaceChildren(...items);
}

function setState(state, message) {
  results.dataset.state = state;
  statusLine.textContent = message;
}

// ---------------------------------------------------------------- plots

const FONT = { family: "system-ui, -apple-system, 'Segoe UI', Roboto, sans-serif", size: 12, color: "#1b1f24" };

const axis = (title, extra = {}) => ({ title: { text: title }, zeroline: false, automargin: true, ...extra });

function layout(xTitle, yTitle, yOptions = {}) {
  return {
    xaxis: axis(xTitle),
    yaxis: axis(yTitle, yOptions),
    margin: { l: 64, r: 16, t: 16, b: 56 },
    legend: { orientation: "h", y: -0.28, x: 0 },
    font: FONT,
    paper_bgcolor: "#ffffff",
    plot_bgcolor: "#ffffff",
    hovermode: "closest",
  };
}

const line = (x, y, name, style = {}) => ({ type: "scatter", mode: "lines", x, y, name, ...style });
const markers = (x, y, name, style = {}) => ({ type: "scatter", mode: "markers", x, y, name, ...style });
const modelLine = (x, y, name) => line(x, y, name, { line: { color: COLORS.design, width: 2 } });
const percent = (fractions) => fractions.map((c) => c * 100);
const kpa = (pascals) => pascals.map((p) => p / 1e3);
const squareMm = (squareMetres) => squareMetres.map((a) => a * 1e6);
const kpaLabel = (pa) => `${fmt(pa / 1e3, 4)} kPa`;

function designMarker(x, y) {
  const marker = { symbol: "star", size: 13, color: COLORS.marker, line: { color: "#1b1f24", width: 1 } };
  return markers([x], [y], "this design", { marker });
}

function measuredMarkers(x, y, name, extra = {}) {
  return markers(x, y, name, { marker: { color: COLORS.measured, size: 9, symbol: "diamond" }, ...extra });
}

/** Static curve at the design pressure; both friction branches at every pressure. */
function hysteresisTraces(outcomes, designPa) {
  const design = outcomes.hysteresis.data;
  const sweep = outcomes.hysteresisOthers?.ok ? outcomes.hysteresisOthers.data : null;
  const others = sweep ? sweep.pressure_pa.map((pa, i) => ({
    pa,
    data: {
      contraction: sweep.contraction,
      force_contracting_n: sweep.force_contracting_n[i],
      force_extending_n: sweep.force_extending_n[i],
    },
    color: OTHER_COLORS[i % OTHER_COLORS.length],
    width: 1.5,
    title: kpaLabel(pa),
  })) : [];
  const curves = [
    { pa: designPa, data: design, color: COLORS.design, width: 2.5, title: `${kpaLabel(designPa)} (design)` },
    ...others,
  ].sort((a, b) => a.pa - b.pa);
  const staticStyle = { line: { color: COLORS.static, dash: "dot", width: 2 } };
  const staticCurve = line(percent(design.contraction), design.force_static_n, `static, ${kpaLabel(designPa)}`, staticStyle);
  return [staticCurve, ...curves.flatMap(({ pa, data, color, width, title }) => {
    const group = { legendgroup: String(pa), legendgrouptitle: { text: title } };
    const x = percent(data.contraction);
    return [
      line(x, data.force_contracting_n, `contracting, ${kpaLabel(pa)}`, { ...group, line: { color, width } }),
      line(x, data.force_extending_n, `extending, ${kpaLabel(pa)}`, { ...group, line: { color, width, dash: "dash" } }),
    ];
  })];
}

function table1Markers() {
  const rows = reference.min_braid_angle_table1;
  const errorBars = { type: "data", array: rows.map((r) => r.std_deg), visible: true, color: COLORS.measured };
  const x = rows.map((r) => r.strand_count);
  const y = rows.map((r) => r.measured_deg);
  return measuredMarkers(x, y, "paper Table 1, measured (±1 s.d.)", { error_y: errorBars });
}

function fittedScaleMarkers() {
  const rows = reference.s_scale_fitted;
  return measuredMarkers(kpa(rows.map((r) => r.pressure_pa)), rows.map((r) => r.s_scale), "fitted to experiments", {
    text: rows.map((r) => r.source),
    hovertemplate: "%{x} kPa: %{y}<br>%{text}<extra></extra>",
  });
}

function failureTraces(sweep, strandCount, angles) {
  const p = kpa(sweep.pressure_pa);
  const worstStyle = { line: { color: COLORS.measured, width: 2, dash: "dash" } };
  const designStyle = { line: { color: COLORS.marker, width: 2 } };
  return [
    modelLine(p, sweep.min_strand_count_exact, `full contraction, ${deg(angles.braid_angle_deg)}`),
    line(p, sweep.worst_case_min_strand_count_exact, `worst case, ${deg(angles.worst_case_braid_angle_deg)}`, worstStyle),
    line([p[0], p[p.length - 1]], [strandCount, strandCount], `this design, N = ${strandCount}`, designStyle),
  ];
}

/**
 * Each plot: the requests it needs, and its traces and layout from their outcomes (o), the
 * design's SI values (v) and the design report (d).
 */
const PLOTS = [
  {
    id: "plot-hysteresis",
    needs: ["hysteresis"],
    traces: (o, v) => hysteresisTraces(o, v.pressure_pa),
    layout: () => layout("Contraction (%)", "Force (N)"),
  },
  {
    id: "plot-theta",
    needs: ["strandSweep"],
    traces: (o, v, d) => [
      modelLine(o.strandSweep.data.strand_count, o.strandSweep.data.min_braid_angle_deg, "model, eq 8"),
      table1Markers(),
      designMarker(v.strand_count, d.min_braid_angle_deg),
    ],
    layout: () => layout("Strand count N", "Minimum braid angle θ<sub>min</sub> (°)"),
  },
  {
    id: "plot-gap",
    needs: ["strandSweep"],
    traces: (o, v, d) => [
      modelLine(o.strandSweep.data.strand_count, squareMm(o.strandSweep.data.max_gap_area_m2), "model, eq 15"),
      designMarker(v.strand_count, d.max_gap_area_m2 * 1e6),
    ],
    layout: () => layout("Strand count N", "Maximum gap area (mm², log scale)", { type: "log", exponentformat: "power" }),
  },
  {
    id: "plot-sscale",
    needs: ["pressureSweep"],
    traces: (o, v, d) => [
      modelLine(kpa(o.pressureSweep.data.pressure_pa), o.pressureSweep.data.s_scale, "Hertz contact, eq 34"),
      fittedScaleMarkers(),
      designMarker(v.pressure_pa / 1e3, d.s_scale),
    ],
    layout: () => layout("Pressure (kPa)", "S<sub>scale</sub>"),
  },
  {
    id: "plot-failure",
    needs: ["pressureSweep"],
    traces: (o, v, d) => failureTraces(o.pressureSweep.data, v.strand_count, d.failure_strand_count),
    layout: () => layout("Pressure (kPa)", "Strands needed to avoid failure"),
  },
];

function plotNote(plotId, messages) {
  const note = document.getElementById(plotId).parentElement.querySelector(".plot-note");
  note.textContent = messages.length ? `Not updated: ${[...new Set(messages)].join(" ")}` : "";
  note.hidden = messages.length === 0;
}

async function drawPlots(outcomes, values, design, errorsByRequest) {
  await plotlyLoaded;
  const draws = PLOTS.map((plot) => {
    const failed = plot.needs.filter((key) => !outcomes[key].ok);
    plotNote(plot.id, failed.flatMap((key) => errorsByRequest[key]));
    if (failed.length) return Promise.resolve();
    const config = PLOT_CONFIG(plot.id.replace("plot-", "pma-"));
    return Plotly.react(plot.id, plot.traces(outcomes, values, design), plot.layout(), config);
  });
  await Promise.all(draws);
}

// ---------------------------------------------------------------- CSV download

function csvCell(value) {
  const s = value === undefined || value === null ? "" : String(value);
  return /[",\n]/.test(s) ? `"${s.replaceAll('"', '""')}"` : s;
}

/** The plotted data as CSV: an x and a y column (and its error bar, if any) per trace. */
function plotCsv(div) {
  const plain = (title) => title.replace(/<[^>]+>/g, "");
  const xTitle = plain(div.layout.xaxis.title.text);
  const yTitle = plain(div.layout.yaxis.title.text);
  const columns = div.data.flatMap((trace) => [
    { head: `${trace.name}: ${xTitle}`, values: Array.from(trace.x) },
    { head: `${trace.name}: ${yTitle}`, values: Array.from(trace.y) },
    ...(trace.error_y?.array ? [{ head: `${trace.name}: standard deviation`, values: trace.error_y.array }] : []),
  ]);
  const rows = Math.max(...columns.map((c) => c.values.length));
  const lines = [columns.map((c) => csvCell(c.head)).join(",")];
  for (let i = 0; i < rows; i += 1) lines.push(columns.map((c) => csvCell(c.values[i])).join(","));
  return `${lines.join("\r\n")}\r\n`;
}

function downloadCsv(button) {
  const div = document.getElementById(button.dataset.plot);
  if (!div.data) return;
  const url = URL.createObjectURL(new Blob([plotCsv(div)], { type: "text/csv" }));
  const link = document.createElement("a");
  link.href = url;
  link.download = button.dataset.file;
  link.click();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

// ---------------------------------------------------------------- recompute cycle

async function recompute() {
  controller?.abort();
  controller = new AbortController();
  const { signal } = controller;
  const started = performance.now();
  const { values, errors } = readForm();
  writeUrl();
  if (errors.size) {
    showErrors(errors);
    setState("invalid", "Fix the highlighted field. The results shown are for the last valid design.");
    return;
  }
  setState("loading", "Computing…");
  const plan = requestPlan(values);
  const outcomes = await runPlan(plan, signal);
  if (signal.aborted) return;
  const { byInput, general, byRequest } = routeErrors(plan, outcomes, values);
  showErrors(byInput, general);
  if (!outcomes.design.ok) {
    setState("invalid", "This design is not valid (see the form). The results shown are for the last valid design.");
    return;
  }
  renderResults(outcomes.design.data, values.strand_count);
  try {
    await drawPlots(outcomes, values, outcomes.design.data, byRequest);
  } catch (error) {
    setState("error", `Results are up to date, but the plots could not be drawn: ${error.message}`);
    return;
  }
  if (signal.aborted) return;
  recordTiming(started);
  setState("ready", resultSummary(outcomes.design.data));
}

function resultSummary(d) {
  const warnings = d.warnings.length ? `${d.warnings.length} warning(s).` : "No warnings.";
  const contraction = `${(d.max_contraction * 100).toFixed(1)} %`;
  return `Up to date: θ_min ${deg(d.min_braid_angle_deg)}, maximum contraction ${contraction}. ${warnings}`;
}

function recordTiming(started) {
  const now = performance.now();
  timings.firstPlotsMs ??= now;
  timings.lastUpdateMs = now - started;
  timings.updates += 1;
}

function scheduleRecompute() {
  clearTimeout(debounceTimer);
  debounceTimer = setTimeout(recompute, DEBOUNCE_MS);
}

// ---------------------------------------------------------------- URL state

function writeUrl() {
  const params = new URLSearchParams();
  for (const element of form.elements) {
    if (!element.name || (element.type === "radio" && !element.checked)) continue;
    if (element.value.trim() !== "") params.set(element.name, element.value.trim());
  }
  history.replaceState(null, "", `?${params}`);
  document.getElementById("share-link").href = location.href;
}

function readUrl() {
  const params = new URLSearchParams(location.search);
  if (params.has("material")) selectMaterial(params.get("material"));
  for (const [name, value] of params) {
    const element = form.elements[name];
    if (!element || name === "material") continue;
    element.value = value; // a RadioNodeList (geometry) takes a value too
  }
}

// ---------------------------------------------------------------- materials and units

const clean = (value) => Number(value.toPrecision(12));

function fillMaterials() {
  const select = form.elements.material;
  select.replaceChildren(...materials.map((m) => new Option(m.name, m.id)));
  selectMaterial(materials.some((m) => m.id === "nylon") ? "nylon" : materials[0]?.id);
}

const PROPERTY_SYMBOLS = {
  youngs_modulus_pa: "E",
  poisson_ratio: "ν",
  tensile_strength_pa: "σu",
  friction_coefficient: "fs",
};

function selectMaterial(id) {
  const material = materials.find((m) => m.id === id);
  if (!material) return;
  form.elements.material.value = id;
  form.elements.E.value = clean(material.youngs_modulus_pa / 1e9);
  form.elements.nu.value = material.poisson_ratio;
  form.elements.su.value = clean(material.tensile_strength_pa / 1e6);
  form.elements.fs.value = material.friction_coefficient;
  const basis = material.basis.charAt(0).toUpperCase() + material.basis.slice(1);
  document.getElementById("material-hint").textContent = `${basis}. Edit the values below freely.`;
  const sources = Object.entries(material.sources).map(([property, source]) => {
    const item = document.createElement("li");
    item.textContent = `${PROPERTY_SYMBOLS[property] ?? property}: ${source}`;
    return item;
  });
  document.getElementById("material-sources").replaceChildren(...sources);
}

function changePressureUnit() {
  const input = form.elements.P;
  const toBar = form.elements.Punit.value === "bar";
  const value = Number(input.value);
  if (input.value.trim() !== "" && Number.isFinite(value)) input.value = clean(toBar ? value / 100 : value * 100);
}

function showGeometryInputs() {
  const mode = geometryMode();
  for (const field of form.querySelectorAll("[data-geometry]")) field.hidden = field.dataset.geometry !== mode;
}

// ---------------------------------------------------------------- start

function wireEvents() {
  form.addEventListener("input", (event) => {
    if (event.target.type === "number") scheduleRecompute();
  });
  form.addEventListener("change", (event) => {
    const name = event.target.name;
    if (name === "material") selectMaterial(event.target.value);
    if (name === "Punit") changePressureUnit();
    if (name === "geometry") showGeometryInputs();
    if (["material", "Punit", "geometry"].includes(name)) recompute();
  });
  form.addEventListener("submit", (event) => event.preventDefault());
  for (const button of document.querySelectorAll("button.csv")) {
    button.addEventListener("click", () => downloadCsv(button));
  }
}

async function start() {
  try {
    [{ materials }, reference] = await Promise.all([api("materials"), api("reference")]);
  } catch (error) {
    setState("error", `Could not load reference data from the API: ${error.message}`);
    return;
  }
  fillMaterials();
  readUrl();
  showGeometryInputs();
  wireEvents();
  await recompute();
}

start();
