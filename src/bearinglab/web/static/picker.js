// The bearing picker: searches the catalog by designation, bore and outside diameter
// (GET /api/catalog/search) and fills the designation field with the bearing chosen.
(function () {
  "use strict";
  const name = document.getElementById("bearing");
  const bore = document.getElementById("search-bore");
  const od = document.getElementById("search-od");
  const list = document.getElementById("matches");
  if (!name || !list) return;
  let timer = null;
  let serial = 0;
  function search() {
    const query = new URLSearchParams();
    if (name.value.trim()) query.set("query", name.value.trim());
    if (bore.value.trim()) query.set("bore", bore.value.trim());
    if (od.value.trim()) query.set("outside_diameter", od.value.trim());
    if (![...query.keys()].length) { list.replaceChildren(); return; }
    query.set("limit", "12");
    const mine = ++serial;
    fetch("/api/catalog/search?" + query.toString())
      .then((r) => r.json())
      .then((doc) => {
        if (mine !== serial) return;
        list.replaceChildren();
        if (!doc.matches) {
          const li = document.createElement("li");
          li.className = "error";
          li.textContent = doc.detail || "no answer";
          list.append(li);
          return;
        }
        for (const row of doc.matches) {
          const li = document.createElement("li");
          const b = document.createElement("button");
          b.type = "button";
          b.className = "match";
          const size = row.bore_mm != null ? ` · ${row.bore_mm} × ${row.outside_diameter_mm} mm` : "";
          b.textContent = `${row.name} (${row.type}${size})`;
          b.dataset.name = row.name;
          b.addEventListener("click", () => { name.value = row.name; list.replaceChildren(); });
          li.append(b);
          list.append(li);
        }
        if (!doc.matches.length) {
          const li = document.createElement("li");
          li.textContent = "no catalog bearing matches";
          list.append(li);
        }
      })
      .catch(() => {});
  }
  for (const input of [name, bore, od]) {
    input.addEventListener("input", () => { clearTimeout(timer); timer = setTimeout(search, 150); });
  }
})();
