// essaim's arena drawing, shared by the replay page and the live page (`essaim serve`):
// both embed this file. A scene S = {minX, minY, sizeX, sizeY, radius, obstacles: [{cylinder,
// movable, x, y, yaw, sx, sy, r, led}], lights: [{x, y, r, g, b}]}; a frame F = {count,
// robot(i) -> {x, y, yaw, color, alive, controllerOk, present (false: added later, not
// drawn; absent: true)}, obstacle(j) -> pose {x, y, yaw, led, gone} or null (it has not
// moved), trail: [[x, y], ...] or null, ids: [...] or null}. The robot count may grow from
// one frame to the next (the loop functions add foot-bots); a robot keeps its index.
function EssaimArenaView(canvas, onSelect) {
  "use strict";
  const ctx = canvas.getContext("2d");
  const TAU = 2 * Math.PI;
  const BODY = "#c8d0d8", DEAD = "#6e6e6e", STATIC = "#4d4d4d", MOVABLE = "#a0522d";
  const rgb = (c) => "rgb(" + c[0] + "," + c[1] + "," + c[2] + ")";
  const view = { x: 0, y: 0, scale: 50 };
  let S = null, F = null, floorImage = null, selected = -1, cssW = 1, cssH = 1;
  const toX = (x) => (x - view.x) * view.scale + cssW / 2;
  const toY = (y) => cssH / 2 - (y - view.y) * view.scale;
  const fromX = (px) => (px - cssW / 2) / view.scale + view.x;
  const fromY = (py) => view.y - (py - cssH / 2) / view.scale;

  function resize() {
    const dpr = window.devicePixelRatio || 1, rect = canvas.getBoundingClientRect();
    cssW = Math.max(1, rect.width); cssH = Math.max(1, rect.height);
    canvas.width = Math.round(cssW * dpr); canvas.height = Math.round(cssH * dpr);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  }
  function fit() {
    if (!S) return;
    view.x = S.minX + S.sizeX / 2; view.y = S.minY + S.sizeY / 2;
    view.scale = 0.96 * Math.min(cssW / S.sizeX, cssH / S.sizeY);
    draw();
  }
  function setScene(scene, floorPngBytes) {
    const first = S === null;
    S = scene; floorImage = null;
    if (floorPngBytes && floorPngBytes.length) {
      createImageBitmap(new Blob([floorPngBytes], { type: "image/png" }))
        .then((img) => { if (S === scene) { floorImage = img; draw(); } })
        .catch(() => {});
    }
    if (first) fit();
  }

  function drawArena(s) {
    const ax = toX(S.minX), ay = toY(S.minY + S.sizeY), aw = S.sizeX * s, ah = S.sizeY * s;
    ctx.fillStyle = "#f4f4f0";
    ctx.fillRect(ax, ay, aw, ah);
    if (floorImage) {
      ctx.imageSmoothingEnabled = false;
      ctx.drawImage(floorImage, ax, ay, aw, ah);
    }
    ctx.strokeStyle = "#888"; ctx.lineWidth = 1;
    ctx.strokeRect(ax, ay, aw, ah);
  }
  function drawObstacles(s) {
    for (let j = 0; j < S.obstacles.length; j++) {
      const o = S.obstacles[j];
      const p = (F && F.obstacle && F.obstacle(j)) || o;  // moved by physics or loop functions
      if (p.gone) continue;  // removed by the loop functions, or not added yet
      ctx.save();
      ctx.translate(toX(p.x), toY(p.y));
      ctx.rotate(-p.yaw);
      ctx.beginPath();
      if (o.cylinder) ctx.arc(0, 0, o.r * s, 0, TAU);
      else ctx.rect(-o.sx * s / 2, -o.sy * s / 2, o.sx * s, o.sy * s);
      ctx.fillStyle = o.movable ? MOVABLE : STATIC;
      ctx.fill();
      if (p.led) {  // its LED colour as an inner disc (loop functions recolour them)
        ctx.beginPath();
        ctx.arc(0, 0, Math.max(2, 0.6 * (o.cylinder ? o.r : Math.min(o.sx, o.sy) / 2) * s), 0, TAU);
        ctx.fillStyle = rgb(p.led);
        ctx.fill();
      }
      ctx.restore();
    }
  }
  function drawLights(s) {
    for (const l of S.lights) {
      const x = toX(l.x), y = toY(l.y), r = Math.max(4, 0.05 * s);
      ctx.beginPath(); ctx.arc(x, y, r, 0, TAU);
      ctx.fillStyle = "rgb(" + l.r + "," + l.g + "," + l.b + ")"; ctx.fill();
      ctx.strokeStyle = "#222"; ctx.lineWidth = 1; ctx.stroke();
    }
  }
  function drawTrail(points) {
    if (!points || points.length < 2) return;
    ctx.beginPath();
    ctx.moveTo(toX(points[0][0]), toY(points[0][1]));
    for (let k = 1; k < points.length; k++) ctx.lineTo(toX(points[k][0]), toY(points[k][1]));
    ctx.strokeStyle = "rgba(255, 196, 0, 0.9)"; ctx.lineWidth = 2; ctx.lineJoin = "round";
    ctx.stroke();
  }
  function drawRobots(s) {
    const r = Math.max(2, S.radius * s);
    let drawn = 0, alive = 0;
    for (let i = 0; i < F.count; i++) {
      const b = F.robot(i);
      if (b.present === false) continue;  // added by the loop functions in a later frame
      const x = toX(b.x), y = toY(b.y);
      ctx.beginPath(); ctx.arc(x, y, r, 0, TAU);
      ctx.globalAlpha = b.alive ? 1 : 0.75;
      ctx.fillStyle = !b.alive ? DEAD : b.color ? rgb(b.color) : BODY;
      ctx.fill();
      ctx.lineWidth = i === selected ? 3 : 1;
      ctx.strokeStyle = i === selected ? "#ffc400" : (b.controllerOk ? "#202020" : "#e00000");
      ctx.stroke();
      ctx.beginPath(); ctx.moveTo(x, y);
      ctx.lineTo(x + Math.cos(b.yaw) * r, y - Math.sin(b.yaw) * r);
      ctx.lineWidth = Math.max(1, r * 0.15); ctx.strokeStyle = "#202020"; ctx.stroke();
      ctx.globalAlpha = 1;
      if (F.ids && r >= 7) {  // ids once robots are big enough to carry them
        ctx.font = Math.min(14, Math.round(r * 0.8)) + "px system-ui, sans-serif";
        ctx.textAlign = "center"; ctx.textBaseline = "top";
        ctx.lineWidth = 3; ctx.strokeStyle = "rgba(255, 255, 255, 0.85)";  // readable on a dark floor too
        ctx.strokeText(F.ids[i], x, y + r + 2);
        ctx.fillStyle = "#111";
        ctx.fillText(F.ids[i], x, y + r + 2);
      }
      if (i === F.highlight) drawHighlight(x, y, r, F.ids ? F.ids[i] : "");
      drawn++;
      alive += b.alive ? 1 : 0;
    }
    canvas.dataset.robotCount = String(drawn);
    return alive;
  }
  /// The robot a debugger stopped on (the live page of `essaim debug --serve`): a ring, and
  /// its id above it at any zoom.
  function drawHighlight(x, y, r, id) {
    const ring = r + Math.max(4, r * 0.6);
    ctx.beginPath(); ctx.arc(x, y, ring, 0, TAU);
    ctx.lineWidth = 3; ctx.strokeStyle = "#ff4fd8"; ctx.stroke();
    ctx.font = "bold 13px system-ui, sans-serif";
    ctx.textAlign = "center"; ctx.textBaseline = "bottom";
    ctx.lineWidth = 3; ctx.strokeStyle = "rgba(255, 255, 255, 0.85)";  // readable on a dark floor too
    ctx.strokeText(id, x, y - ring - 2);
    ctx.fillStyle = "#b0008a";
    ctx.fillText(id, x, y - ring - 2);
    canvas.dataset.highlighted = id;
  }
  /// Draws the frame set last (or `frame`); returns how many robots are alive.
  function draw(frame) {
    if (frame) F = frame;
    ctx.save();
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = "#1e2227";
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    ctx.restore();
    if (!S) return 0;
    const s = view.scale;
    drawArena(s);
    drawObstacles(s);
    drawLights(s);
    if (!F) return 0;
    canvas.dataset.highlighted = "";
    if (selected >= 0) drawTrail(F.trail);
    return drawRobots(s);
  }

  function robotAt(px, py) {
    if (!F || !S) return -1;
    let best = -1, bestD = Infinity;
    const pick = Math.max(S.radius * view.scale, 6) + 3;
    for (let i = 0; i < F.count; i++) {
      const b = F.robot(i), d = Math.hypot(toX(b.x) - px, toY(b.y) - py);
      if (d < bestD && b.present !== false) { bestD = d; best = i; }
    }
    return bestD <= pick ? best : -1;
  }
  function select(i) { selected = i; draw(); if (onSelect) onSelect(i); }

  // ---- input: click selects, drag pans, wheel zooms --------------------------------------
  let drag = null;
  canvas.addEventListener("pointerdown", (e) => {
    drag = { x: e.offsetX, y: e.offsetY, vx: view.x, vy: view.y, moved: false };
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener("pointermove", (e) => {
    if (!drag) return;
    const dx = e.offsetX - drag.x, dy = e.offsetY - drag.y;
    if (!drag.moved && Math.hypot(dx, dy) < 4) return;
    drag.moved = true;
    canvas.classList.add("dragging");
    view.x = drag.vx - dx / view.scale; view.y = drag.vy + dy / view.scale;
    draw();
  });
  canvas.addEventListener("pointerup", (e) => {
    if (drag && !drag.moved) select(robotAt(e.offsetX, e.offsetY));
    drag = null;
    canvas.classList.remove("dragging");
  });
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    const wx = fromX(e.offsetX), wy = fromY(e.offsetY);
    view.scale = Math.min(1e5, Math.max(1, view.scale * Math.exp(-e.deltaY * 0.0015)));
    view.x = wx - (e.offsetX - cssW / 2) / view.scale;  // keep the point under the cursor
    view.y = wy + (e.offsetY - cssH / 2) / view.scale;
    draw();
  }, { passive: false });
  window.addEventListener("resize", () => { resize(); draw(); });
  resize();

  return {
    setScene, draw, fit, select, robotAt,
    selected: () => selected,
    canvasPosition: (x, y) => ({ x: toX(x), y: toY(y) }),
  };
}
