// Time-series charts, shared by the replay page and the live page: one small chart per
// column of the run's time series (timeseries.csv), against its "tick" column when it has
// one, with a legend of the columns' colours and values.
function EssaimCharts(container) {
  "use strict";
  const COLORS = ["#4e9af1", "#f1a84e", "#5ec46b", "#e0605a", "#b48cf0", "#d8c44a", "#4ad0c8", "#f07cc4"];
  const MAX_CHARTS = 8;
  let columns = [], rows = [], cursor = null, pending = false;
  if (!document.getElementById("essaim-charts-style")) {
    const style = document.createElement("style");
    style.id = "essaim-charts-style";
    style.textContent = ".legend-item { display: inline-block; margin: 0 10px 2px 0; white-space: nowrap; }" +
      ".legend-item i { display: inline-block; width: 10px; height: 10px; margin-right: 4px; border-radius: 2px; }" +
      ".legend-item b { font-weight: normal; margin-left: 5px; color: #dde; font-variant-numeric: tabular-nums; }" +
      "canvas.chart { display: block; width: 100%; height: 64px; margin-top: 4px; }";
    document.head.append(style);
  }
  const legend = document.createElement("div");
  legend.className = "legend";
  const charts = document.createElement("div");
  container.append(legend, charts);

  const xIndex = () => columns.indexOf("tick");
  const plotted = () => columns.map((c, k) => k).filter((k) => k !== xIndex()).slice(0, MAX_CHARTS);

  function build() {
    legend.textContent = "";
    charts.textContent = "";
    plotted().forEach((k, n) => {
      const item = document.createElement("span");
      item.className = "legend-item";
      item.innerHTML = '<i style="background:' + COLORS[n % COLORS.length] + '"></i>';
      item.append(document.createTextNode(columns[k]));
      const value = document.createElement("b");
      item.append(value);
      legend.append(item);
      const canvas = document.createElement("canvas");
      canvas.className = "chart";
      canvas.title = columns[k];
      charts.append(canvas);
    });
    container.style.display = columns.length ? "" : "none";
  }
  function drawOne(canvas, k, color) {
    const dpr = window.devicePixelRatio || 1, w = canvas.clientWidth || 240, h = canvas.clientHeight || 60;
    canvas.width = Math.round(w * dpr); canvas.height = Math.round(h * dpr);
    const c = canvas.getContext("2d");
    c.setTransform(dpr, 0, 0, dpr, 0, 0);
    c.clearRect(0, 0, w, h);
    if (!rows.length) return;
    const xi = xIndex(), X = (r, i) => (xi >= 0 ? r[xi] : i);
    let x0 = X(rows[0], 0), x1 = X(rows[rows.length - 1], rows.length - 1), lo = Infinity, hi = -Infinity;
    for (const r of rows) if (Number.isFinite(r[k])) { lo = Math.min(lo, r[k]); hi = Math.max(hi, r[k]); }
    if (!Number.isFinite(lo)) return;
    if (hi === lo) { hi += 1; lo -= 1; }
    if (x1 === x0) x1 = x0 + 1;
    const px = (x) => 2 + (x - x0) / (x1 - x0) * (w - 4), py = (y) => h - 12 - (y - lo) / (hi - lo) * (h - 16);
    const step = Math.max(1, Math.floor(rows.length / (2 * w)));  // about two points per pixel
    c.beginPath();
    for (let i = 0; i < rows.length; i += step) {
      const v = rows[i][k];
      if (!Number.isFinite(v)) continue;
      if (i === 0) c.moveTo(px(X(rows[i], i)), py(v)); else c.lineTo(px(X(rows[i], i)), py(v));
    }
    const last = rows.length - 1;
    if (Number.isFinite(rows[last][k])) c.lineTo(px(X(rows[last], last)), py(rows[last][k]));
    c.strokeStyle = color; c.lineWidth = 1.5; c.stroke();
    c.fillStyle = "#99a"; c.font = "10px system-ui, sans-serif"; c.textBaseline = "bottom";
    c.fillText(columns[k] + "  " + fmt(lo) + " .. " + fmt(hi), 3, h);
    if (cursor !== null && cursor >= x0 && cursor <= x1) {
      c.fillStyle = "rgba(255,196,0,0.8)"; c.fillRect(px(cursor) - 0.5, 0, 1, h - 12);
    }
  }
  const fmt = (v) => (Math.abs(v) >= 1e4 || (v !== 0 && Math.abs(v) < 1e-2) ? v.toExponential(2) : String(+v.toFixed(3)));
  /// The value of column k at the cursor (replay) or the last row (live).
  function valueAt(k) {
    if (!rows.length) return "";
    let r = rows[rows.length - 1];
    const xi = xIndex();
    if (cursor !== null && xi >= 0) {
      let lo = 0, hi = rows.length;
      while (lo < hi) { const mid = (lo + hi) >> 1; if (rows[mid][xi] <= cursor) lo = mid + 1; else hi = mid; }
      if (lo === 0) return "";
      r = rows[lo - 1];
    }
    return Number.isFinite(r[k]) ? fmt(r[k]) : String(r[k]);
  }
  function draw() {
    pending = false;
    const canvases = charts.querySelectorAll("canvas"), values = legend.querySelectorAll("b");
    plotted().forEach((k, n) => {
      drawOne(canvases[n], k, COLORS[n % COLORS.length]);
      values[n].textContent = valueAt(k);
    });
  }
  function later() { if (!pending) { pending = true; requestAnimationFrame(draw); } }

  build();
  return {
    /// Replaces everything: columns and rows.
    set(cols, rs) { columns = cols || []; rows = rs || []; build(); later(); },
    append(rs) { if (rs.length) { rows.push(...rs); later(); } },
    setCursor(x) { cursor = x; later(); },
    rowCount: () => rows.length,
    columns: () => columns.slice(),
  };
}
