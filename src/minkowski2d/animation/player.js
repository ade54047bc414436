/* minkowski2d animation player.
 *
 * Plays back a merge trace computed in Python (minkowski2d.merge_trace). Everything drawn
 * comes from the embedded data: vertices, edge vectors, the sum's vertices, label and icon
 * positions, the configuration-space polygons. The only arithmetic here is the affine map
 * from world coordinates to the SVG's pixels (and back, to place a dragged vertex), and
 * counting steps. No cross products, no sums of coordinates, no geometry.
 */
(function () {
  "use strict";

  var SVGNS = "http://www.w3.org/2000/svg";
  var D = JSON.parse(document.getElementById("mk-data").textContent);
  var S = { k: 0, timer: null, drag: null, inflight: false, pending: null, requests: 0 };

  function $(id) { return document.getElementById(id); }

  function el(tag, attrs, parent, text) {
    var n = document.createElementNS(SVGNS, tag);
    if (attrs) { for (var key in attrs) { if (attrs[key] !== null && attrs[key] !== undefined) n.setAttribute(key, attrs[key]); } }
    if (text !== undefined) n.textContent = text;
    if (parent) parent.appendChild(n);
    return n;
  }

  function html(tag, attrs, parent, text) {
    var n = document.createElement(tag);
    if (attrs) { for (var key in attrs) n.setAttribute(key, attrs[key]); }
    if (text !== undefined) n.textContent = text;
    if (parent) parent.appendChild(n);
    return n;
  }

  function clear(node) { while (node.firstChild) node.removeChild(node.firstChild); }

  function N() { return D.trace.steps.length; }

  /* ---- the view map: world -> SVG pixels (the view box comes from Python) ---- */
  function mapper(view) {
    var b = view.box, s = view.px / (b[2] - b[0]);
    return {
      X: function (x) { return (x - b[0]) * s; },
      Y: function (y) { return (b[3] - y) * s; },
      P: function (p) { return ((p[0] - b[0]) * s) + "," + ((b[3] - p[1]) * s); },
      inv: function (px, py) { return [b[0] + px / s, b[3] - py / s]; },
      view: view
    };
  }

  function pts(m, list) { return list.map(m.P).join(" "); }

  function defs(svg, id) {
    var d = el("defs", null, svg);
    [["a", "var(--a)"], ["b", "var(--b)"], ["s", "var(--s)"]].forEach(function (c) {
      var mk = el("marker", {
        id: id + "-arr-" + c[0], viewBox: "0 0 10 10", refX: 9, refY: 5, markerWidth: 9,
        markerHeight: 9, markerUnits: "userSpaceOnUse", orient: "auto-start-reverse"
      }, d);
      el("path", { d: "M0,0 L10,5 L0,10 z", style: "fill:" + c[1] }, mk);
    });
  }

  function grid(svg, m) {
    var v = m.view, g = el("g", { "class": "grid" }, svg), px = v.px;
    var every = v.ticks_x.length > 11 ? 2 : 1;
    v.ticks_x.forEach(function (t, i) {
      var x = m.X(t);
      el("line", { x1: x, y1: 0, x2: x, y2: px }, g);
      if (i % every === 0 && x < px - 28) el("text", { x: x + 2, y: px - 3 }, g, v.labels_x[i]);
    });
    v.ticks_y.forEach(function (t, i) {
      var y = m.Y(t);
      el("line", { x1: 0, y1: y, x2: px, y2: y }, g);
      if (i % every === 0 && y > 12) el("text", { x: 2, y: y - 2 }, g, v.labels_y[i]);
    });
    if (v.axis_x) el("line", { "class": "axis", x1: 0, y1: m.Y(0), x2: px, y2: m.Y(0) }, g);
    if (v.axis_y) el("line", { "class": "axis", x1: m.X(0), y1: 0, x2: m.X(0), y2: px }, g);
  }

  function shape(svg, m, list, cls) {
    if (list.length === 1) return el("circle", { cx: m.X(list[0][0]), cy: m.Y(list[0][1]), r: 5, "class": cls }, svg);
    return el("polygon", { points: pts(m, list), "class": cls }, svg);
  }

  function arrow(svg, m, p, q, cls, markerId) {
    return el("line", {
      x1: m.X(p[0]), y1: m.Y(p[1]), x2: m.X(q[0]), y2: m.Y(q[1]), "class": cls,
      "marker-end": "url(#" + markerId + ")"
    }, svg);
  }

  /* ---- which edges are taken by step k ---- */
  function edgeState(k) {
    var st = { A: {}, B: {}, nowA: {}, nowB: {}, nextA: null, nextB: null };
    var steps = D.trace.steps;
    for (var s = 0; s < k; s++) {
      steps[s].taken.forEach(function (t) {
        st[t.source][t.index] = true;
        if (s === k - 1) st["now" + t.source][t.index] = true;
      });
    }
    if (k < steps.length) { st.nextA = steps[k].i; st.nextB = steps[k].j; }
    return st;
  }

  function edgeClass(src, idx, es) {
    var c = "edge " + src.toLowerCase();
    if (es["now" + src][idx]) return c + " now";
    if (es[src][idx]) return c;
    if (es["next" + src] === idx) return c + " next";
    return c + " pending";
  }

  /* ---- scene 1: A and B, each in its own picture ---- */
  function drawInputs(k) {
    var es = edgeState(k), T = D.trace;
    [["A", "svg-a", D.a_view, T.a, T.a_text, D.edges_a], ["B", "svg-b", D.b_view, T.b, T.b_text, D.edges_b]].forEach(function (g) {
      var src = g[0], low = src.toLowerCase(), svg = $(g[1]), m = mapper(g[2]);
      svg.setAttribute("viewBox", "0 0 " + g[2].px + " " + g[2].px);
      clear(svg); defs(svg, low); grid(svg, m);
      shape(svg, m, g[3], "poly-" + low);
      g[5].forEach(function (e, idx) {
        var line = arrow(svg, m, e.from, e.to, edgeClass(src, idx, es), low + "-arr-" + low);
        el("title", null, line, e.label + " = " + T["edges_" + low + "_text"][idx]);
        if (e.label_fits || es["now" + src][idx] || es["next" + src] === idx) {
          el("text", { x: m.X(e.label_at[0]), y: m.Y(e.label_at[1]), "class": "elabel " + low }, svg, e.label);
        }
      });
      g[3].forEach(function (p, idx) {
        var dot = el("circle", { cx: m.X(p[0]), cy: m.Y(p[1]), r: idx === 0 ? 5 : 3, "class": idx === 0 ? "vdot first" : "vdot" }, svg);
        el("title", null, dot, src + "[" + idx + "] = " + g[4][idx]);
      });
      var p0 = g[3][0];
      el("text", { x: m.X(p0[0]) + 6, y: m.Y(p0[1]) + 17, "class": "vlabel" }, svg, src + "[0]");
      if (D.editable) drawHandles(svg, m, src, g[3]);
    });
  }

  /* ---- scene 2: the sum so far ---- */
  function drawSum(k) {
    var svg = $("svg-sum"), m = mapper(D.sum_view), T = D.trace, steps = T.steps, n = steps.length;
    clear(svg); defs(svg, "sum"); grid(svg, m);
    if (n > 0 && k === n) shape(svg, m, T.result, "sum-fill");
    for (var s = 0; s < k; s++) {
      var st = steps[s];
      for (var t = 0; t + 1 < st.path.length; t++) {
        var low = st.path_sources[t].toLowerCase();
        var line = arrow(svg, m, st.path[t], st.path[t + 1], "sum-edge " + low + (s === k - 1 ? " now" : ""), "sum-arr-" + low);
        el("title", null, line, "step " + st.index + ": " + (low === "a" ? "a" : "b") + st.taken[t].index);
      }
    }
    var start = T.start;
    el("circle", { cx: m.X(start[0]), cy: m.Y(start[1]), r: 6, "class": "start" }, svg);
    var sright = m.X(start[0]) > 0.6 * m.view.px;
    el("text", { x: m.X(start[0]) + (sright ? -8 : 8), y: m.Y(start[1]) + 18, "class": "vlabel" + (sright ? " end" : "") }, svg,
      "A[0]+B[0] = " + T.start_text);
    var cur = k === 0 ? start : steps[k - 1].vertex;
    var curText = k === 0 ? T.start_text : steps[k - 1].vertex_text;
    el("circle", { cx: m.X(cur[0]), cy: m.Y(cur[1]), r: 5, "class": "cur" }, svg);
    if (k > 0 && k < n) {
      // keep the label inside the picture: to the left of the vertex on the right side
      var right = m.X(cur[0]) > 0.6 * m.view.px;
      el("text", { x: m.X(cur[0]) + (right ? -10 : 8), y: m.Y(cur[1]) - 8, "class": "vlabel" + (right ? " end" : "") }, svg, curText);
    }
  }

  /* ---- text panels ---- */
  function edgeName(t) {
    var T = D.trace, low = t.source.toLowerCase();
    return low + t.index + " = " + T["edges_" + low + "_text"][t.index] + " from " + t.source;
  }

  function drawInfo(k) {
    var T = D.trace, n = N();
    $("info-step").textContent = n === 0 ? "Nothing to merge" : "Step " + k + " of " + n;
    if (n === 0) {
      $("info-edge").textContent = "A and B are single points: A \u2295 B is the point A[0] + B[0] = " + T.start_text + ".";
      $("info-why").textContent = "";
      $("info-vertex").textContent = "";
      return;
    }
    if (k === 0) {
      $("info-edge").textContent = "Start at A[0] + B[0] = " + T.a_text[0] + " + " + T.b_text[0] + " = " + T.start_text +
        ", the bottom-most vertex of the sum.";
      var s0 = T.steps[0];
      $("info-why").textContent = "Next: " + (s0.i === null ? "" : "a" + s0.i) + (s0.i !== null && s0.j !== null ? " and " : "") +
        (s0.j === null ? "" : "b" + s0.j) + (s0.i !== null && s0.j !== null ? " are compared." : " is the only edge left.");
      $("info-vertex").textContent = "Current vertex: " + T.start_text;
      return;
    }
    var st = T.steps[k - 1];
    $("info-edge").textContent = "Took " + st.taken.map(edgeName).join(" and ") + (st.taken.length > 1 ? ", together." : ".");
    $("info-why").textContent = "Why: " + st.why + ".";
    $("info-vertex").textContent = k === n
      ? "Back at the start " + st.vertex_text + ": the boundary is closed. A \u2295 B has " + T.result.length +
        " vertices: " + T.result_text.join(", ") + "."
      : "Reached vertex " + st.vertex_text + ".";
  }

  function drawEdgeLists(k) {
    var T = D.trace, es = edgeState(k);
    [["A", "edges-a", T.edges_a_text, D.icons_a], ["B", "edges-b", T.edges_b_text, D.icons_b]].forEach(function (g) {
      var ol = $(g[1]), low = g[0].toLowerCase();
      clear(ol);
      ol.className = "edges " + low;
      if (g[2].length === 0) { html("li", null, ol, g[0] + " is a point: no edges"); return; }
      g[2].forEach(function (txt, idx) {
        var cls = es["now" + g[0]][idx] ? "taken now" : es[g[0]][idx] ? "taken" : es["next" + g[0]] === idx ? "next" : "";
        var li = html("li", { "class": cls }, ol);
        var icon = el("svg", { viewBox: "0 0 24 24", "aria-hidden": "true" }, li);
        var ic = D["icons_" + low][idx];
        el("line", {
          x1: ic[0][0], y1: ic[0][1], x2: ic[1][0], y2: ic[1][1], "class": "edge " + low,
          style: "stroke-width:2", "marker-end": "url(#ic-arr-" + low + ")"
        }, icon);
        li.appendChild(document.createTextNode(low + idx + " " + txt));
      });
      var focus = ol.querySelector("li.now") || ol.querySelector("li.next");
      if (focus && ol.scrollHeight > ol.clientHeight) ol.scrollTop = focus.offsetTop - 30;  // offsetParent is the list
    });
  }

  function drawLog(k) {
    var ol = $("log"), steps = D.trace.steps;
    $("log-start").textContent = "0. start at A[0] + B[0] = " + D.trace.start_text;
    while (ol.children.length > k) ol.removeChild(ol.lastChild);
    while (ol.children.length < k) html("li", null, ol, steps[ol.children.length].log);
    if (ol.lastChild) ol.scrollTop = ol.scrollHeight;
  }

  function drawResult(k) {
    var T = D.trace, n = N(), ol = $("result");
    clear(ol);
    if (k < n) {
      $("result-note").textContent = "Listed when the merge is complete (" + (n - k) + " more step" + (n - k === 1 ? "" : "s") + ").";
      return;
    }
    var r = T.result.length;
    $("result-note").textContent = "A \u2295 B: " + (r === 1 ? "1 vertex (a point)" : r === 2 ? "2 vertices (a segment)" :
      r + " vertices, counter-clockwise from the bottom-most") + " (" + T.kind + " coordinates).";
    T.result_text.forEach(function (t) { html("li", null, ol, t); });
  }

  function drawControls(k) {
    var n = N(), scrub = $("scrub");
    scrub.max = String(n);
    scrub.value = String(k);
    $("counter").textContent = "Step " + k + " of " + n;
    $("btn-back").disabled = k === 0;
    $("btn-step").disabled = k === n;
    $("btn-reset").disabled = k === 0 && !S.timer;
    $("btn-run").disabled = n === 0;
    document.body.setAttribute("data-step", String(k));
    document.body.setAttribute("data-steps", String(n));
  }

  /* ---- configuration space ---- */
  function drawCspace() {
    var C = D.cspace, pos = Math.min(parseInt($("cs-pos").value, 10) || 0, C.positions.length - 1);
    var f = $("svg-frame"), mf = mapper(C.frame_view);
    f.setAttribute("viewBox", "0 0 " + C.frame_view.px + " " + C.frame_view.px);
    clear(f); grid(f, mf);
    shape(f, mf, C.robot, "robot");
    shape(f, mf, C.reflected, "negrobot");
    el("circle", { cx: mf.X(0), cy: mf.Y(0), r: 5, "class": "ref" }, f);
    el("text", { x: mf.X(0) + 8, y: mf.Y(0) + 18, "class": "vlabel" }, f, "reference point");

    var w = $("svg-cspace"), mw = mapper(C.work_view);
    clear(w); grid(w, mw);
    shape(w, mw, C.inflated, "infl");
    shape(w, mw, C.obstacle, "obst");
    C.positions.forEach(function (p, idx) {
      if (idx !== pos) shape(w, mw, p.robot, "robot ghost");
    });
    var P = C.positions[pos];
    shape(w, mw, P.robot, "robot");
    C.positions.forEach(function (p) { el("circle", { cx: mw.X(p.ref[0]), cy: mw.Y(p.ref[1]), r: 2.5, "class": "ref" }, w); });
    el("circle", { cx: mw.X(P.ref[0]), cy: mw.Y(P.ref[1]), r: 6, "class": "ref" }, w);

    var slider = $("cs-pos");
    slider.max = String(C.positions.length - 1);
    slider.value = String(pos);
    $("cs-pos-out").textContent = pos + ": " + P.ref_text;
    $("cs-linked").textContent = C.linked ? "Here the obstacle is A and the robot is B, so the inflated obstacle is A \u2295 (\u2212B)." : "";
    $("cs-text").textContent = "obstacle: " + C.obstacle_text.join(" ") + " \u00b7 robot: " + C.robot_text.join(" ") +
      " \u00b7 \u2212robot: " + C.reflected_text.join(" ") + " \u00b7 obstacle \u2295 (\u2212robot): " + C.inflated_text.join(" ");
  }

  /* ---- playback ---- */
  function show(k) {
    var n = N();
    S.k = Math.max(0, Math.min(n, k));
    drawInputs(S.k); drawSum(S.k); drawInfo(S.k); drawEdgeLists(S.k); drawLog(S.k); drawResult(S.k); drawControls(S.k);
  }

  function setRunning(on) {
    var b = $("btn-run");
    if (S.timer) { clearInterval(S.timer); S.timer = null; }
    if (on) {
      S.timer = setInterval(function () {
        if (S.k >= N()) { setRunning(false); return; }
        show(S.k + 1);
        if (S.k >= N()) setRunning(false);
      }, parseInt($("speed").value, 10));
    }
    b.querySelector("path").setAttribute("d", on ? "M3 2h4v12H3zM9 2h4v12H9z" : "M4 2v12l10-6z");
    b.querySelector(".lbl").textContent = on ? "Pause" : "Run";
    b.setAttribute("aria-label", on ? "Pause" : "Run");
    document.body.setAttribute("data-running", on ? "true" : "false");
    drawControls(S.k);
  }

  function toggleRun() {
    if (S.timer) { setRunning(false); return; }
    if (S.k >= N()) show(0);
    if (N() > 0) setRunning(true);
  }

  function step() { setRunning(false); show(S.k + 1); }
  function back() { setRunning(false); show(S.k - 1); }
  function reset() { setRunning(false); show(0); }

  $("btn-step").addEventListener("click", step);
  $("btn-back").addEventListener("click", back);
  $("btn-reset").addEventListener("click", reset);
  $("btn-run").addEventListener("click", toggleRun);
  $("speed").addEventListener("change", function () { if (S.timer) setRunning(true); });
  $("scrub").addEventListener("input", function () {
    var k = parseInt(this.value, 10);  // read first: pausing redraws the controls
    setRunning(false);
    show(k);
  });
  $("cs-pos").addEventListener("input", drawCspace);

  function typing(t) {
    if (!t || !t.tagName) return false;
    var tag = t.tagName;
    return tag === "TEXTAREA" || tag === "SELECT" || (tag === "INPUT" && t.type !== "range" && t.type !== "checkbox");
  }

  document.addEventListener("keydown", function (e) {
    if (e.ctrlKey || e.metaKey || e.altKey || typing(e.target)) return;
    var onRange = e.target.tagName === "INPUT" && e.target.type === "range";
    if (e.key === "ArrowRight" && !onRange) { e.preventDefault(); step(); }
    else if (e.key === "ArrowLeft" && !onRange) { e.preventDefault(); back(); }
    else if (e.key === " " || e.key === "Spacebar") { e.preventDefault(); if (!e.repeat) toggleRun(); }
    else if (e.key === "r" || e.key === "R") { e.preventDefault(); reset(); }
  });
  // a focused button would also "click" on the space key's release: the keydown above handled it
  document.addEventListener("keyup", function (e) {
    if ((e.key === " " || e.key === "Spacebar") && !typing(e.target)) e.preventDefault();
  });

  /* ---- served mode: edit, ask the server, keep the last good state ---- */
  function fieldText(id) { var v = $(id).value.trim(); return v === "" ? null : v; }

  function fillEditor() {
    $("edit-a").value = D.trace.a_text.join("\n");
    $("edit-b").value = D.trace.b_text.join("\n");
    $("edit-hull").checked = !!D.hull;
  }

  // the server's errors are {type, message, argument, vertex, hint} (or, from an older
  // server, a plain string)
  function errorText(e) {
    if (!e) return "";
    if (typeof e === "string") return e;
    var m = String(e.message || "the server refused the input");
    if (e.hint && m.indexOf(e.hint) < 0) m += " (hint: " + e.hint + ")";
    return m;
  }

  function showError(msg) {
    var e = $("error");
    if (msg) { e.textContent = msg; e.hidden = false; } else { e.textContent = ""; e.hidden = true; }
  }

  function request(body) {
    if (S.inflight) { S.pending = body; return; }
    S.inflight = true;
    $("edit-status").textContent = "computing\u2026";
    fetch(D.api, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) })
      .then(function (r) { return r.json().then(function (j) { return { ok: r.ok, j: j }; }); })
      .then(function (res) {
        if (res.ok && !res.j.error) {
          var keepEnd = S.k >= N();
          var editable = D.editable, api = D.api;
          D = res.j; D.editable = editable; D.api = api;
          showError(null);
          $("edit-status").textContent = "Updated: " + N() + " steps.";
          $("edit-status").className = "status";
          if (!S.drag) fillEditor();
          show(keepEnd ? N() : S.k);
          drawCspace();
        } else {
          var why = errorText(res.j.error) || "the server refused the input";
          showError(why);
          $("edit-status").textContent = "Not applied: " + why + ". The last good polygons are kept.";
          $("edit-status").className = "status bad";
          if (!S.drag) show(S.k);
        }
      })
      .catch(function (err) {
        showError("cannot reach the server: " + err.message);
        $("edit-status").textContent = "";
      })
      .then(function () {
        S.inflight = false;
        S.requests += 1;
        document.body.setAttribute("data-requests", String(S.requests));
        if (S.pending) { var p = S.pending; S.pending = null; request(p); }
      });
  }

  function body(a, b, view) {
    return {
      a: a, b: b, obstacle: fieldText("edit-obstacle"), robot: fieldText("edit-robot"),
      hull: $("edit-hull").checked, view: view || null
    };
  }

  function apply() {
    request(body($("edit-a").value, $("edit-b").value, null));
  }

  function drawHandles(svg, m, src, list) {
    list.forEach(function (p, idx) {
      var dragging = S.drag && S.drag.src === src && S.drag.idx === idx;
      var x = dragging ? S.drag.px : m.X(p[0]), y = dragging ? S.drag.py : m.Y(p[1]);
      var h = el("circle", {
        cx: x, cy: y, r: 9, "class": "handle " + src.toLowerCase() + (dragging ? " dragging" : ""),
        "data-src": src, "data-idx": idx
      }, svg);
      el("title", null, h, "drag " + src + "[" + idx + "]");
    });
  }

  function svgPoint(svg, e) {
    var pt = svg.createSVGPoint();
    pt.x = e.clientX; pt.y = e.clientY;
    var q = pt.matrixTransform(svg.getScreenCTM().inverse());
    return [q.x, q.y];
  }

  function snapped(v, view) {
    var s = view.snap, r = Math.round(v / s) * s;
    if (view.snap_int) return String(Math.round(r));
    return String(parseFloat(r.toPrecision(12)));
  }

  function dragMove(e) {
    if (!S.drag) return;
    var svg = $(S.drag.svg), q = svgPoint(svg, e), m = mapper(S.drag.view);
    // inside the picture: its view is held while dragging (the server then keeps it)
    S.drag.px = Math.max(0, Math.min(S.drag.view.px, q[0]));
    S.drag.py = Math.max(0, Math.min(S.drag.view.px, q[1]));
    var w = m.inv(S.drag.px, S.drag.py);
    var txt = "(" + snapped(w[0], S.drag.view) + ", " + snapped(w[1], S.drag.view) + ")";
    if (txt === S.drag.last) { drawInputs(S.k); return; }
    S.drag.last = txt;
    var poly = S.drag.base.slice();
    poly[S.drag.idx] = txt;
    var a = S.drag.src === "A" ? poly.join("\n") : S.drag.otherA;
    var b = S.drag.src === "B" ? poly.join("\n") : S.drag.otherB;
    drawInputs(S.k);
    S.drag.lastBody = body(a, b, { a: D.a_view.box, b: D.b_view.box });
    request(S.drag.lastBody);
  }

  function dragEnd() {
    if (!S.drag) return;
    var last = S.drag.lastBody;
    S.drag = null;
    if (last) { last.view = null; request(last); }  // the final polygons, views fitted anew
    window.removeEventListener("pointermove", dragMove);
    window.removeEventListener("pointerup", dragEnd);
    window.removeEventListener("pointercancel", dragEnd);
    fillEditor();
    show(S.k);
  }

  if (D.editable) {
    $("editor").hidden = false;
    $("drag-hint").hidden = false;
    fillEditor();
    $("btn-apply").addEventListener("click", apply);
    ["svg-a", "svg-b"].forEach(function (id) {
      $(id).addEventListener("pointerdown", function (e) {
        var t = e.target;
        if (!t.classList || !t.classList.contains("handle")) return;
        e.preventDefault();
        var src = t.getAttribute("data-src"), idx = parseInt(t.getAttribute("data-idx"), 10);
        S.drag = {
          src: src, idx: idx, svg: id, view: src === "A" ? D.a_view : D.b_view, last: null,
          base: (src === "A" ? D.trace.a_text : D.trace.b_text).slice(),
          otherA: D.trace.a_text.join("\n"), otherB: D.trace.b_text.join("\n"),
          px: parseFloat(t.getAttribute("cx")), py: parseFloat(t.getAttribute("cy"))
        };
        window.addEventListener("pointermove", dragMove);
        window.addEventListener("pointerup", dragEnd);
        window.addEventListener("pointercancel", dragEnd);
      });
    });
  }

  show(0);
  drawCspace();
  document.body.setAttribute("data-ready", "true");
})();
