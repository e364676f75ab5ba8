// The shaft-system editor of the calculator page (issue 33). Its tables of sections, supports, loads and
// gears, with the file's other lines, make the file the form posts (TOML, in the field "shaft"); the shaft
// is drawn to scale from the tables as the user types. A TOML file uploaded is posted as it is, and the
// page reads it back into the tables (web/shaft.py): no TOML reader is needed here. The file can be
// downloaded as the tables make it.
(function () {
  "use strict";
  const root = document.getElementById("shaft-editor");
  const file = document.getElementById("shaft");
  if (!root || !file) return;
  const other = document.getElementById("shaft-other");
  const svg = document.getElementById("shaft-drawing");
  const note = document.getElementById("shaft-drawing-note");
  const form = document.getElementById("form");
  const NS = "http://www.w3.org/2000/svg";
  const TABLES = ["sections", "supports", "loads", "gears"];
  // metres per unit: the lengths the drawing reads (the calculation reads every unit of bearinglab.units)
  const LENGTH = { m: 1, cm: 1e-2, mm: 1e-3, um: 1e-6, "µm": 1e-6, micron: 1e-6, in: 0.0254, inch: 0.0254, ft: 0.3048 };
  const LENGTHS = { sections: ["length", "diameter", "bore"], supports: ["position"], loads: ["position"],
                    gears: ["position", "pitch_diameter"] };
  const EXAMPLE = {  // a gear shaft on two deep-groove bearings, one of them locating
    other: 'speed = "1500 rpm"\n\n[lubricant]\noil = "VG68"\ntemperature = "60 degC"',
    sections: [{ length: "40 mm", diameter: "35 mm" }, { length: "180 mm", diameter: "45 mm" },
               { length: "40 mm", diameter: "35 mm" }],
    supports: [{ name: "A", position: "20 mm", kind: "bearing", value: "6207", axial: true },
               { name: "B", position: "240 mm", kind: "bearing", value: "6207", axial: false }],
    loads: [{ name: "coupling", position: "0 mm", more: 'mz = "-120 N*m"' }],
    gears: [{ name: "gear", position: "90 mm", pitch_diameter: "150 mm", pressure_angle: "20 deg",
              helix_angle: "0 deg", torque: "120 N*m", mesh_angle: "0 deg" }],
  };

  function length(text) {
    const m = /^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([A-Za-zµ]+)\s*$/.exec(text || "");
    if (!m || LENGTH[m[2]] === undefined) return null;
    return parseFloat(m[1]) * LENGTH[m[2]];
  }

  function cells(tr) {
    const out = {};
    for (const el of tr.querySelectorAll("[data-key]")) out[el.dataset.key] = el.type === "checkbox" ? el.checked : el.value.trim();
    return out;
  }

  function rows(name) {
    return [...root.querySelectorAll(`table[data-table="${name}"] tbody tr.row`)].map(cells);
  }

  function line(key, value) { return `${key} = ${JSON.stringify(value)}`; }  // a JSON string is a TOML string

  function toml(name, row) {
    const lines = [`[[${name}]]`];
    if (name === "supports") {
      if (row.name) lines.push(line("name", row.name));
      if (row.position) lines.push(line("position", row.position));
      if (row.kind === "bearing" && row.value) lines.push(line("bearing", row.value));
      if (row.kind === "set") {
        for (const [key, cell] of [["bearing", "value"], ["arrangement", "arrangement"], ["preload", "preload"]]) {
          if (row[cell]) lines.push(line(`bearing_set.${key}`, row[cell]));
        }
      }
      if (row.kind === "linear" && row.value) lines.push(line("radial_stiffness", row.value));
      if (row.kind === "rigid") lines.push("rigid = true");
      lines.push(`axial = ${row.axial ? "true" : "false"}`);
    } else {
      for (const [key, value] of Object.entries(row)) if (key !== "more" && value) lines.push(line(key, value));
    }
    if (row.more) lines.push(row.more);
    return lines.join("\n");
  }

  function compose() {
    const parts = [];
    if (other.value.trim()) parts.push(other.value.trim());
    for (const name of TABLES) for (const row of rows(name)) parts.push(toml(name, row));
    return parts.length ? parts.join("\n\n") + "\n" : "";
  }

  function el(tag, attrs, text) {
    const e = document.createElementNS(NS, tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    if (text !== undefined) e.textContent = text;
    svg.append(e);
    return e;
  }

  function mark() {  // a length the drawing cannot read is marked at its cell
    for (const [name, keys] of Object.entries(LENGTHS)) {
      for (const tr of root.querySelectorAll(`table[data-table="${name}"] tbody tr.row`)) {
        for (const key of keys) {
          const input = tr.querySelector(`[data-key="${key}"]`);
          const bad = input.value.trim() !== "" && length(input.value) === null;
          input.classList.toggle("bad", bad);
          input.title = bad ? "a length with its unit, e.g. 25 mm" : "";
        }
      }
    }
  }

  function draw() {
    svg.replaceChildren();
    const sections = [];
    let z = 0;
    for (const r of rows("sections")) {
      const l = length(r.length), d = length(r.diameter), b = r.bore ? length(r.bore) : 0;
      if (!(l > 0) || !(d > 0)) continue;
      sections.push({ z, l, d, b: b > 0 && b < d ? b : 0 });
      z += l;
    }
    const at = (r) => ({ ...r, z: length(r.position) });
    const supports = rows("supports").map(at).filter((r) => r.z !== null);
    const loads = rows("loads").map(at).filter((r) => r.z !== null);
    const gears = rows("gears").map(at).filter((r) => r.z !== null).map((g) => ({ ...g, d: length(g.pitch_diameter) || 0 }));
    const span = Math.max(z, ...supports.map((s) => s.z), ...loads.map((s) => s.z), ...gears.map((s) => s.z));
    if (!(span > 0)) {
      svg.setAttribute("viewBox", "0 0 1000 40");
      el("text", { x: 500, y: 25, class: "s-label", "text-anchor": "middle" }, "add the sections of the shaft: length and diameter");
      return;
    }
    const radius = (zz) => {
      const s = sections.find((q) => zz >= q.z - 1e-12 && zz <= q.z + q.l + 1e-12);
      return s ? s.d / 2 : Math.max(0, ...sections.map((q) => q.d / 2));
    };
    const rmax = Math.max(1e-9, ...sections.map((s) => s.d / 2), ...gears.map((g) => g.d / 2));
    const width = 1000, pad = 50, scale = (width - 2 * pad) / span, top = 70;
    const cy = top + rmax * scale, height = cy + rmax * scale + 60;
    const x = (zz) => pad + zz * scale;
    svg.setAttribute("viewBox", `0 0 ${width} ${Math.ceil(height)}`);
    el("line", { x1: x(0) - 20, x2: x(span) + 20, y1: cy, y2: cy, class: "s-axis" });
    for (const s of sections) {
      el("rect", { x: x(s.z), y: cy - (s.d / 2) * scale, width: s.l * scale, height: s.d * scale, class: "s-section" });
      if (s.b) el("rect", { x: x(s.z), y: cy - (s.b / 2) * scale, width: s.l * scale, height: s.b * scale, class: "s-bore" });
    }
    for (const g of gears) {
      const h = Math.max(g.d, 2 * radius(g.z)) * scale;
      el("rect", { x: x(g.z) - 4, y: cy - h / 2, width: 8, height: h, class: "s-gear" });
      el("text", { x: x(g.z), y: cy - h / 2 - 6, class: "s-label", "text-anchor": "middle" }, g.name || "gear");
    }
    for (const s of supports) {
      const r = radius(s.z) * scale, size = Math.max(12, Math.min(26, r * 0.6));
      for (const side of [-1, 1]) {
        const y0 = side < 0 ? cy - r - size : cy + r;
        if (s.kind === "rigid") {
          const tip = side < 0 ? cy - r : cy + r, base = side < 0 ? tip - size : tip + size;
          el("path", { d: `M${x(s.z)},${tip} L${x(s.z) - size / 2},${base} L${x(s.z) + size / 2},${base} Z`, class: "s-bearing" });
        } else if (s.kind === "linear") {
          const pts = [];
          for (let k = 0; k <= 6; k++) pts.push(`${x(s.z) + (k % 2 ? 5 : -5) * (k > 0 && k < 6)},${y0 + (k * size) / 6}`);
          el("polyline", { points: pts.join(" "), class: "s-spring" });
        } else {
          const n = s.kind === "set" ? 2 : 1;
          for (let k = 0; k < n; k++) {
            const x0 = x(s.z) - (n * size) / 2 + k * size;
            el("rect", { x: x0, y: y0, width: size, height: size, class: "s-bearing" });
            el("circle", { cx: x0 + size / 2, cy: y0 + size / 2, r: size / 4, class: "s-ball" });
          }
        }
        if (s.axial && side > 0) el("circle", { cx: x(s.z), cy: y0 + size + 8, r: 4, class: "s-axial" });
      }
      el("text", { x: x(s.z), y: cy + r + size + 26, class: "s-label", "text-anchor": "middle" }, s.name || "");
    }
    for (const l of loads) {
      const y1 = cy - radius(l.z) * scale - 2;
      el("line", { x1: x(l.z), x2: x(l.z), y1: y1 - 36, y2: y1 - 8, class: "s-load" });
      el("path", { d: `M${x(l.z)},${y1} L${x(l.z) - 5},${y1 - 10} L${x(l.z) + 5},${y1 - 10} Z`, class: "s-load-head" });
      const given = ["fx", "fy", "fz", "mx", "my"].filter((k) => l[k]).map((k) => `${k} ${l[k]}`).join(", ");
      const anchor = x(l.z) < width / 4 ? "start" : x(l.z) > (3 * width) / 4 ? "end" : "middle";  // inside the drawing
      el("text", { x: x(l.z) + (anchor === "start" ? -8 : anchor === "end" ? 8 : 0), y: y1 - 42, class: "s-label",
                   "text-anchor": anchor }, [l.name, given].filter(Boolean).join(": "));
    }
    el("text", { x: x(span), y: height - 8, class: "s-label", "text-anchor": "end" },
       `${+(span * 1000).toPrecision(6)} mm, to scale`);
    note.textContent = `The shaft: ${sections.length} sections, ${supports.length} supports, ${loads.length} loads, ` +
      `${gears.length} gears, drawn to scale from the tables (● locates axially).`;
  }

  function update() {
    file.value = compose();
    mark();
    draw();
  }

  function addRow(name, values) {
    const template = document.getElementById(`shaft-row-${name}`);
    const tr = template.content.querySelector("tr").cloneNode(true);
    for (const [key, value] of Object.entries(values || {})) {
      const input = tr.querySelector(`[data-key="${key}"]`);
      if (!input) continue;
      if (input.type === "checkbox") input.checked = !!value; else input.value = value;
    }
    root.querySelector(`table[data-table="${name}"] tbody`).append(tr);
    return tr;
  }

  root.addEventListener("input", update);
  root.addEventListener("change", update);
  root.addEventListener("click", (event) => {
    const add = event.target.closest("button.add");
    const remove = event.target.closest("button.remove");
    if (add) {
      const tr = addRow(add.dataset.add);
      update();
      tr.querySelector("input, select").focus();
    } else if (remove) {
      remove.closest("tr").remove();
      update();
    }
  });
  document.getElementById("shaft-example").addEventListener("click", () => {
    for (const tbody of root.querySelectorAll("table.edit tbody")) tbody.replaceChildren();
    other.value = EXAMPLE.other;
    for (const name of TABLES) for (const row of EXAMPLE[name] || []) addRow(name, row);
    update();
  });
  document.getElementById("shaft-download").addEventListener("click", () => {
    const blob = new Blob([file.value], { type: "application/toml" });
    const a = document.createElement("a");
    a.href = URL.createObjectURL(blob);
    a.download = "shaft.toml";
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  });
  const upload = document.getElementById("shaft-upload");
  upload.addEventListener("change", () => {
    const chosen = upload.files && upload.files[0];
    if (!chosen) return;
    chosen.text().then((text) => {  // the page reads it into the tables and computes it
      file.readOnly = false;
      file.value = text;
      form.requestSubmit ? form.requestSubmit() : form.submit();
    });
  });

  file.readOnly = true;  // the tables and the other lines make the file
  file.title = "The file the tables and the other lines make (upload a file to replace them)";
  if (file.value.trim() || root.querySelector("tbody tr.row")) update(); else draw();
})();
