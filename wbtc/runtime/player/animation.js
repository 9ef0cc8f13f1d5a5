/* wbtc animation player: plays back a run recorded with the Supervisor's animationStartRecording.
 *
 * The page holds the data as JSON (script#wbtc-animation): visual geoms attached to bodies, meshes,
 * and frames that carry the poses (position + quaternion w, x, y, z, z up) that changed since the
 * previous frame, LED colour changes and supervisor labels. Drawn with WebGL 1, lit from the camera.
 * Textured planes, boxes and meshes get their texture coordinates as MuJoCo computes them.
 * Mouse: drag to turn around, shift-drag or right-drag to pan, wheel to zoom. Space plays/pauses.
 */
"use strict";

var WbtcPlayer = (function () {
  // ---- 4x4 matrices, column-major as WebGL wants them ----
  function identity() {
    return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  }

  function multiply(a, b) {
    var out = new Array(16);
    for (var c = 0; c < 4; c++) {
      for (var r = 0; r < 4; r++) {
        var s = 0;
        for (var k = 0; k < 4; k++) s += a[k * 4 + r] * b[c * 4 + k];
        out[c * 4 + r] = s;
      }
    }
    return out;
  }

  // Rigid pose (position, quaternion w x y z) with a scale along the local axes.
  function pose(p, q, s) {
    var w = q[0], x = q[1], y = q[2], z = q[3];
    var sx = s ? s[0] : 1, sy = s ? s[1] : 1, sz = s ? s[2] : 1;
    return [
      (1 - 2 * (y * y + z * z)) * sx, 2 * (x * y + w * z) * sx, 2 * (x * z - w * y) * sx, 0,
      2 * (x * y - w * z) * sy, (1 - 2 * (x * x + z * z)) * sy, 2 * (y * z + w * x) * sy, 0,
      2 * (x * z + w * y) * sz, 2 * (y * z - w * x) * sz, (1 - 2 * (x * x + y * y)) * sz, 0,
      p[0], p[1], p[2], 1,
    ];
  }

  function perspective(fovy, aspect, near, far) {
    var f = 1 / Math.tan(fovy / 2);
    return [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) / (near - far), -1,
      0, 0, 2 * far * near / (near - far), 0];
  }

  function lookAt(eye, target, up) {
    var z = normalize(sub(eye, target));
    var x = normalize(cross(up, z));
    var y = cross(z, x);
    return [x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0,
      -dot(x, eye), -dot(y, eye), -dot(z, eye), 1];
  }

  function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
  function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
  function normalize(a) {
    var n = Math.sqrt(dot(a, a)) || 1;
    return [a[0] / n, a[1] / n, a[2] / n];
  }

  var INFINITE_PLANE = 50;  // half size drawn for an infinite plane (MuJoCo size 0), metres

  // ---- unit shapes as flat arrays of triangles: positions and normals (meshes: and uvs) ----
  function box() {
    var p = [], n = [];
    var faces = [[0, 1], [0, -1], [1, 1], [1, -1], [2, 1], [2, -1]];
    faces.forEach(function (f) {
      var a = f[0], sign = f[1], u = (a + 1) % 3, v = (a + 2) % 3;
      var corners = [[-1, -1], [1, -1], [1, 1], [-1, -1], [1, 1], [-1, 1]];
      corners.forEach(function (c) {
        var q = [0, 0, 0], m = [0, 0, 0];
        q[a] = sign; q[u] = c[0] * sign; q[v] = c[1];
        m[a] = sign;
        p.push(q[0], q[1], q[2]); n.push(m[0], m[1], m[2]);
      });
    });
    return {positions: p, normals: n};
  }

  function sphere(zFrom, zTo) {
    // Latitude band of a unit sphere between polar angles zFrom and zTo (0 = +z pole).
    var p = [], n = [], rings = 12, segments = 20;
    function vertex(i, j) {
      var theta = zFrom + (zTo - zFrom) * i / rings, phi = 2 * Math.PI * j / segments;
      return [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];
    }
    for (var i = 0; i < rings; i++) {
      for (var j = 0; j < segments; j++) {
        var a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
        [a, b, c, a, c, d].forEach(function (v) { p.push(v[0], v[1], v[2]); n.push(v[0], v[1], v[2]); });
      }
    }
    return {positions: p, normals: n};
  }

  function cylinder(caps) {
    // Radius 1, from z = -1 to z = 1.
    var p = [], n = [], segments = 24;
    for (var j = 0; j < segments; j++) {
      var a0 = 2 * Math.PI * j / segments, a1 = 2 * Math.PI * (j + 1) / segments;
      var c0 = Math.cos(a0), s0 = Math.sin(a0), c1 = Math.cos(a1), s1 = Math.sin(a1);
      p.push(c0, s0, -1, c1, s1, -1, c1, s1, 1, c0, s0, -1, c1, s1, 1, c0, s0, 1);
      n.push(c0, s0, 0, c1, s1, 0, c1, s1, 0, c0, s0, 0, c1, s1, 0, c0, s0, 0);
      if (caps) {
        p.push(0, 0, 1, c0, s0, 1, c1, s1, 1, 0, 0, -1, c1, s1, -1, c0, s0, -1);
        n.push(0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, -1, 0, 0, -1);
      }
    }
    return {positions: p, normals: n};
  }

  function plane() {
    return {positions: [-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0, -1, 1, 0],
      normals: [0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]};
  }

  function mesh(m) {
    // Flat shading: every triangle gets its own normal; m.uv holds every face corner's (u, v).
    var p = [], n = [], t = [], v = m.vertices, f = m.faces;
    for (var i = 0; i < f.length; i += 3) {
      var a = [v[3 * f[i]], v[3 * f[i] + 1], v[3 * f[i] + 2]];
      var b = [v[3 * f[i + 1]], v[3 * f[i + 1] + 1], v[3 * f[i + 1] + 2]];
      var c = [v[3 * f[i + 2]], v[3 * f[i + 2] + 1], v[3 * f[i + 2] + 2]];
      var nn = normalize(cross(sub(b, a), sub(c, a)));
      [a, b, c].forEach(function (q) { p.push(q[0], q[1], q[2]); n.push(nn[0], nn[1], nn[2]); });
      for (var k = 0; k < 3; k++) t.push(m.uv ? m.uv[2 * (i + k)] : 0, m.uv ? m.uv[2 * (i + k) + 1] : 0);
    }
    return {positions: p, normals: n, uvs: t};
  }

  // The draw items of one geom: a shape and its local matrix (MuJoCo sizes are half sizes and radii).
  function items(geom) {
    var s = geom.size, local = function (scale, offset) {
      var m = pose(geom.pos, geom.quat, null);
      return multiply(m, pose(offset || [0, 0, 0], [1, 0, 0, 0], scale));
    };
    switch (geom.type) {
      case "box": return [["box", local([s[0], s[1], s[2]])]];
      case "sphere": return [["sphere", local([s[0], s[0], s[0]])]];
      case "ellipsoid": return [["sphere", local([s[0], s[1], s[2]])]];
      case "cylinder": return [["cylinder", local([s[0], s[0], s[1]])]];
      case "capsule": return [["tube", local([s[0], s[0], s[1]])],
        ["top", local([s[0], s[0], s[0]], [0, 0, s[1]])], ["bottom", local([s[0], s[0], s[0]], [0, 0, -s[1]])]];
      case "plane": return [["plane", local([s[0] > 0 ? s[0] : INFINITE_PLANE, s[1] > 0 ? s[1] : INFINITE_PLANE, 1])]];
      case "mesh": return [["mesh" + geom.mesh, local([1, 1, 1])]];
    }
    return [];
  }

  // How a textured geom's unit shape maps to texture coordinates, as MuJoCo maps them (u right, v down
  // from the image's top row): {mode: 1 plane, 2 box, 3 mesh, map: [a, b, c, d], tex: image index}.
  // Plane: u = a x + b, v = c y + d over the unit square; a finite side spans the image once, an
  // infinite one runs half an image per metre, shifted by half an image. Box: each face from its two
  // other axes. Mesh: its own coordinates. All scaled by the repeat factors.
  function texturing(geom) {
    var t = geom.texture;
    if (!t) return null;
    var r = t.repeat, s = geom.size;
    if (geom.type === "plane") {
      var shift = s[0] > 0 && s[1] > 0 ? 0 : 0.5;
      var a = s[0] > 0 ? 0.5 * r[0] : 0.5 * INFINITE_PLANE * r[0], b = (s[0] > 0 ? 0.5 * r[0] : 0) - shift;
      var c = s[1] > 0 ? -0.5 * r[1] : -0.5 * INFINITE_PLANE * r[1], d = (s[1] > 0 ? 0.5 * r[1] : 0) - shift;
      return {mode: 1, map: [a, b, c, d], tex: t.tex};
    }
    if (geom.type === "box") return {mode: 2, map: [r[0], 0, r[1], 0], tex: t.tex};
    if (geom.type === "mesh") return {mode: 3, map: [r[0], 0, r[1], 0], tex: t.tex};
    return null;
  }

  // Every frame's full state (poses, colours, labels), carrying forward what did not change.
  function timeline(data) {
    var poses = [], colours = [], labels = [];
    var current = new Float64Array(data.bodies.length * 7);
    for (var b = 0; b < data.bodies.length; b++) current[b * 7 + 3] = 1;
    var rgba = data.geoms.map(function (g) { return g.rgba.slice(); });
    var text = {};
    data.frames.forEach(function (frame) {
      frame.p.forEach(function (e) { for (var k = 0; k < 7; k++) current[e[0] * 7 + k] = e[k + 1]; });
      (frame.c || []).forEach(function (e) { rgba[e[0]] = e.slice(1); });
      if (frame.l) text = frame.l;
      poses.push(Float64Array.from(current));
      colours.push(rgba.map(function (c) { return c.slice(); }));
      labels.push(text);
    });
    return {poses: poses, colours: colours, labels: labels};
  }

  // The index of the last frame at or before time t.
  function frameAt(frames, t) {
    var lo = 0, hi = frames.length - 1;
    if (hi < 0) return -1;
    while (lo < hi) {
      var mid = (lo + hi + 1) >> 1;
      if (frames[mid].t <= t + 1e-9) lo = mid; else hi = mid - 1;
    }
    return lo;
  }

  // `mode` is declared mediump in both shaders: a uniform they share must have one precision.
  var VERTEX = "attribute vec3 position; attribute vec3 normal; attribute vec2 uv; uniform mat4 mvp;" +
    "uniform mat4 model; uniform mat3 normals; uniform mediump float mode; uniform vec4 uvMap;" +
    "varying vec3 n; varying vec3 world; varying vec2 tc;" +
    "void main() { n = normals * normal; world = (model * vec4(position, 1.0)).xyz;" +
    " if (mode < 1.5) { tc = vec2(uvMap.x * position.x + uvMap.y, uvMap.z * position.y + uvMap.w); }" +
    " else if (mode < 2.5) { vec2 p = abs(normal.x) > 0.5 ? position.yz : (abs(normal.y) > 0.5 ? position.xz : position.xy);" +
    "  tc = vec2((p.x + 1.0) * 0.5 * uvMap.x, (1.0 - p.y) * 0.5 * uvMap.z); }" +
    " else { tc = uv * uvMap.xz; }" +
    " gl_Position = mvp * vec4(position, 1.0); }";
  var FRAGMENT = "precision mediump float; uniform vec4 color; uniform vec3 eye; uniform float mode;" +
    "uniform sampler2D image; varying vec3 n; varying vec3 world; varying vec2 tc;" +
    "void main() { vec3 l = normalize(eye - world); float d = abs(dot(normalize(n), l));" +
    " vec3 base = mode > 0.5 ? color.rgb * texture2D(image, tc).rgb : color.rgb;" +
    " gl_FragColor = vec4(base * (0.35 + 0.65 * d), color.a); }";

  function Player(doc, win) {
    this.doc = doc;
    this.win = win;
    this.data = JSON.parse(doc.getElementById("wbtc-animation").textContent);
    this.canvas = doc.getElementById("view");
    this.gl = this.canvas.getContext("webgl", {antialias: true});
    this.state = timeline(this.data);
    this.items = [];
    var self = this;
    this.data.geoms.forEach(function (geom, index) {
      var texture = texturing(geom);
      items(geom).forEach(function (it) {
        self.items.push({shape: it[0], local: it[1], body: geom.body, geom: index, texture: texture});
      });
    });
    this.textures = [];  // WebGL textures by image index, each null until its image has loaded
    this.time = 0;
    this.playing = true;
    this.orbit = startView(this.data.camera, this.state.poses[0], this.data.bodies.length);
  }

  // Orbit parameters (target, distance, yaw, pitch) from the Viewpoint's position and direction.
  function startView(camera, poses, count) {
    var centre = [0, 0, 0];
    for (var b = 0; b < count && poses; b++) {
      for (var k = 0; k < 3; k++) centre[k] += poses[b * 7 + k] / count;
    }
    var f = normalize(camera.forward), ahead = dot(sub(centre, camera.position), f);
    var distance = ahead > 0.05 ? ahead : 1.0;
    var target = [0, 1, 2].map(function (k) { return camera.position[k] + f[k] * distance; });
    var v = sub(camera.position, target);
    return {target: target, distance: distance, yaw: Math.atan2(v[1], v[0]),
      pitch: Math.asin(Math.max(-1, Math.min(1, v[2] / distance))), fovy: camera.fovy * Math.PI / 180};
  }

  Player.prototype.eye = function () {
    var o = this.orbit, c = Math.cos(o.pitch);
    return [o.target[0] + o.distance * c * Math.cos(o.yaw), o.target[1] + o.distance * c * Math.sin(o.yaw),
      o.target[2] + o.distance * Math.sin(o.pitch)];
  };

  Player.prototype.setup = function () {
    var gl = this.gl, self = this;
    var program = gl.createProgram();
    [[gl.VERTEX_SHADER, VERTEX], [gl.FRAGMENT_SHADER, FRAGMENT]].forEach(function (s) {
      var shader = gl.createShader(s[0]);
      gl.shaderSource(shader, s[1]);
      gl.compileShader(shader);
      gl.attachShader(program, shader);
    });
    gl.linkProgram(program);
    if (gl.getProgramParameter && !gl.getProgramParameter(program, gl.LINK_STATUS)) {
      throw new Error("wbtc player: the shaders do not link: " + gl.getProgramInfoLog(program));
    }
    gl.useProgram(program);
    this.program = program;
    this.loc = {};
    ["mvp", "model", "normals", "color", "eye", "mode", "uvMap", "image"].forEach(function (u) {
      self.loc[u] = gl.getUniformLocation(program, u);
    });
    this.attr = {position: gl.getAttribLocation(program, "position"), normal: gl.getAttribLocation(program, "normal"),
      uv: gl.getAttribLocation(program, "uv")};
    var shapes = {box: box(), sphere: sphere(0, Math.PI), cylinder: cylinder(true), tube: cylinder(false),
      top: sphere(0, Math.PI / 2), bottom: sphere(Math.PI / 2, Math.PI), plane: plane()};
    this.data.meshes.forEach(function (m, i) { shapes["mesh" + i] = mesh(m); });
    this.buffers = {};
    Object.keys(shapes).forEach(function (name) {
      var s = shapes[name], pb = gl.createBuffer(), nb = gl.createBuffer(), tb = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, pb);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(s.positions), gl.STATIC_DRAW);
      gl.bindBuffer(gl.ARRAY_BUFFER, nb);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(s.normals), gl.STATIC_DRAW);
      gl.bindBuffer(gl.ARRAY_BUFFER, tb);  // only meshes have their own; the others compute theirs
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(s.uvs || new Array(s.positions.length / 3 * 2).fill(0)),
        gl.STATIC_DRAW);
      self.buffers[name] = {positions: pb, normals: nb, uvs: tb, count: s.positions.length / 3};
    });
    this.loadTextures();
    gl.enable(gl.DEPTH_TEST);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
  };

  // Each image becomes a repeating, mipmapped texture once the browser has decoded it.
  Player.prototype.loadTextures = function () {
    var gl = this.gl, self = this;
    (this.data.textures || []).forEach(function (url, index) {
      self.textures.push(null);
      if (typeof Image === "undefined") return;
      var image = new Image();
      image.onload = function () {
        var texture = gl.createTexture();
        gl.bindTexture(gl.TEXTURE_2D, texture);
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, gl.RGBA, gl.UNSIGNED_BYTE, image);
        gl.generateMipmap(gl.TEXTURE_2D);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
        self.textures[index] = texture;
      };
      image.src = url;
    });
  };

  // Draw the frame at this.time; returns the number of draw calls.
  Player.prototype.draw = function () {
    var gl = this.gl, data = this.data, self = this;
    var width = this.canvas.clientWidth || 640, height = this.canvas.clientHeight || 480;
    if (this.canvas.width !== width || this.canvas.height !== height) {
      this.canvas.width = width;
      this.canvas.height = height;
    }
    gl.viewport(0, 0, width, height);
    var bg = data.background;
    gl.clearColor(bg[0], bg[1], bg[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    var f = Math.max(0, frameAt(data.frames, this.time));
    var poses = this.state.poses[f], colours = this.state.colours[f];
    var eye = this.eye();
    var view = multiply(perspective(this.orbit.fovy, width / height, 0.01, 1000), lookAt(eye, this.orbit.target, [0, 0, 1]));
    gl.uniform3fv(this.loc.eye, eye);
    var calls = 0;
    // Opaque items first, then the transparent ones over them.
    [false, true].forEach(function (transparent) {
      self.items.forEach(function (it) {
        var rgba = colours[it.geom];
        if ((rgba[3] < 0.999) !== transparent) return;
        var b = it.body * 7;
        var body = pose([poses[b], poses[b + 1], poses[b + 2]], [poses[b + 3], poses[b + 4], poses[b + 5], poses[b + 6]]);
        var model = multiply(body, it.local);
        gl.uniformMatrix4fv(self.loc.mvp, false, multiply(view, model));
        gl.uniformMatrix4fv(self.loc.model, false, model);
        gl.uniformMatrix3fv(self.loc.normals, false, normalMatrix(model));
        gl.uniform4fv(self.loc.color, rgba);
        var texture = it.texture && self.textures[it.texture.tex];
        gl.uniform1f(self.loc.mode, texture ? it.texture.mode : 0);
        if (texture) {
          gl.bindTexture(gl.TEXTURE_2D, texture);
          gl.uniform4fv(self.loc.uvMap, it.texture.map);
        }
        var buffer = self.buffers[it.shape];
        gl.bindBuffer(gl.ARRAY_BUFFER, buffer.positions);
        gl.enableVertexAttribArray(self.attr.position);
        gl.vertexAttribPointer(self.attr.position, 3, gl.FLOAT, false, 0, 0);
        gl.bindBuffer(gl.ARRAY_BUFFER, buffer.normals);
        gl.enableVertexAttribArray(self.attr.normal);
        gl.vertexAttribPointer(self.attr.normal, 3, gl.FLOAT, false, 0, 0);
        gl.bindBuffer(gl.ARRAY_BUFFER, buffer.uvs);
        gl.enableVertexAttribArray(self.attr.uv);
        gl.vertexAttribPointer(self.attr.uv, 2, gl.FLOAT, false, 0, 0);
        gl.drawArrays(gl.TRIANGLES, 0, buffer.count);
        calls++;
      });
    });
    this.showLabels(this.state.labels[f], width, height);
    return calls;
  };

  // Normals go through the inverse transpose of the model matrix's 3x3 part.
  function normalMatrix(m) {
    var a = m[0], b = m[1], c = m[2], d = m[4], e = m[5], f = m[6], g = m[8], h = m[9], i = m[10];
    var det = a * (e * i - f * h) - d * (b * i - c * h) + g * (b * f - c * e) || 1;
    return [(e * i - f * h) / det, (g * f - d * i) / det, (d * h - g * e) / det,
      (h * c - b * i) / det, (a * i - g * c) / det, (g * b - a * h) / det,
      (b * f - e * c) / det, (d * c - a * f) / det, (a * e - d * b) / det];
  }

  Player.prototype.showLabels = function (labels, width, height) {
    var box = this.doc.getElementById("labels");
    if (!box || this.shownLabels === labels) return;
    this.shownLabels = labels;
    box.innerHTML = "";
    var self = this;
    Object.keys(labels).sort(function (a, b) { return a - b; }).forEach(function (id) {
      var l = labels[id];
      if (!l[0]) return;
      var div = self.doc.createElement("div");
      div.textContent = l[0];
      div.style.left = (l[1] * width) + "px";
      div.style.top = (l[2] * height) + "px";
      div.style.fontSize = Math.max(1, Math.round(l[3] * height)) + "px";
      div.style.color = l[4];
      div.style.opacity = String(1 - l[5]);
      box.appendChild(div);
    });
  };

  Player.prototype.controls = function () {
    var self = this, canvas = this.canvas, doc = this.doc;
    var play = doc.getElementById("play"), slider = doc.getElementById("time"), clock = doc.getElementById("clock");
    slider.max = String(this.data.duration);
    play.textContent = this.playing ? "Pause" : "Play";
    this.toggle = function () {
      if (!self.playing && self.time >= self.data.duration) self.time = 0;
      self.playing = !self.playing;
      play.textContent = self.playing ? "Pause" : "Play";
    };
    play.addEventListener("click", this.toggle);
    slider.addEventListener("input", function () { self.time = parseFloat(slider.value); });
    this.showTime = function () {
      slider.value = String(self.time);
      clock.textContent = self.time.toFixed(2) + " s";
    };
    var drag = null;
    canvas.addEventListener("contextmenu", function (e) { e.preventDefault(); });
    canvas.addEventListener("mousedown", function (e) { drag = {x: e.clientX, y: e.clientY, pan: e.button === 2 || e.shiftKey}; });
    this.win.addEventListener("mouseup", function () { drag = null; });
    this.win.addEventListener("mousemove", function (e) {
      if (!drag) return;
      var dx = e.clientX - drag.x, dy = e.clientY - drag.y, o = self.orbit;
      drag.x = e.clientX;
      drag.y = e.clientY;
      if (drag.pan) {
        var scale = o.distance * 0.002, right = [-Math.sin(o.yaw), Math.cos(o.yaw), 0];
        var up = cross(normalize(sub(self.eye(), o.target)), right);
        for (var k = 0; k < 3; k++) o.target[k] += (-dx * right[k] + dy * up[k]) * scale;
      } else {
        o.yaw -= dx * 0.01;
        o.pitch = Math.max(-1.55, Math.min(1.55, o.pitch + dy * 0.01));
      }
    });
    canvas.addEventListener("wheel", function (e) {
      e.preventDefault();
      self.orbit.distance = Math.max(0.01, self.orbit.distance * Math.exp(e.deltaY * 0.001));
    });
    this.win.addEventListener("keydown", function (e) { if (e.key === " ") { e.preventDefault(); self.toggle(); } });
  };

  // Advance by `seconds` of wall-clock time when playing (the animation plays in real time).
  Player.prototype.advance = function (seconds) {
    if (!this.playing) return;
    this.time = Math.min(this.time + seconds, this.data.duration);
    if (this.time >= this.data.duration) this.toggle();
  };

  Player.prototype.start = function () {
    var self = this, last = null;
    this.setup();
    this.controls();
    function tick(now) {
      if (last !== null) self.advance((now - last) / 1000);
      last = now;
      self.showTime();
      self.draw();
      self.win.requestAnimationFrame(tick);
    }
    this.win.requestAnimationFrame(tick);
  };

  return {Player: Player, frameAt: frameAt, timeline: timeline, items: items, texturing: texturing, pose: pose,
    multiply: multiply};
})();

if (typeof document !== "undefined" && document.getElementById("wbtc-animation")) {
  new WbtcPlayer.Player(document, window).start();
}
