#include "marker/station/operator_page.hpp"

namespace mark {

// It listens to /api/events (no polling) and re-reads /api/status and /api/preview when an
// event arrives; the buttons POST to the same endpoints an MES uses. The next part's picture
// (/api/preview.png) is fetched again whenever the next part's job or text changes (a part
// ended, a SET, another job loaded).
// The page itself holds no data, so it is served without a token (marker serve --token): every
// request its script makes goes through fetch() with `Authorization: Bearer` once the operator
// typed the token (asked for on the first 401, kept in sessionStorage: gone with the tab).
// EventSource cannot send that header, so the event stream is read with fetch() and a stream
// reader too — one code path with and without a token — and the picture is fetched as a blob.
std::string_view operator_page_html() {
  static constexpr std::string_view kPage = R"html(<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>marker station</title>
<meta name="viewport" content="width=device-width, initial-scale=1">
<style>
body{font:16px system-ui,sans-serif;margin:1.5em;max-width:48em}
#state{font-size:2em;font-weight:bold;padding:.2em .6em;border-radius:.3em;display:inline-block}
.idle{background:#cfc}.marking{background:#ffc}.paused{background:#ddd}.error{background:#fcc}
pre{background:#f4f4f4;padding:.5em;font-size:1.3em;white-space:pre-wrap}
button{font-size:1.3em;margin-right:.5em;padding:.3em 1em}
table{border-collapse:collapse}td,th{padding:.1em .8em .1em 0;text-align:left}
#message{color:#a00}
#picture{max-width:100%;border:1px solid #ccc}
</style></head><body>
<h1>marker station</h1>
<div>State: <span id="state">…</span> &nbsp; job <code id="job"></code></div>
<p><button id="mark">Mark</button><button id="abort">Abort</button><button id="pause">Pause</button><button id="reset">Reset</button></p>
<p id="message"></p>
<form id="login" hidden>This station needs its token: <input id="token" type="password" autocomplete="current-password" size="40">
<button type="submit">Use token</button></form>
<h2>Next mark</h2><pre id="next">…</pre>
<img id="picture" alt="the next part as the simulated scanner marks it">
<h2>Last part</h2>
<table><tr><td>id</td><td id="last_id">–</td></tr>
<tr><td>outcome</td><td id="last_outcome">–</td></tr>
<tr><td>serials</td><td id="last_serials">–</td></tr>
<tr><td>mark time</td><td id="last_time">–</td></tr></table>
<pre id="last_text">–</pre>
<h2>Counts</h2><div id="counts">–</div>
<h2>Last 50 marks</h2>
<table id="log"><thead><tr><th>id</th><th>time (UTC)</th><th>text</th><th>serials</th><th>outcome</th></tr></thead><tbody></tbody></table>
<script>
"use strict";
const $ = id => document.getElementById(id);
// The token the operator typed (marker serve --token), for this tab only.
function headers() {
  const t = sessionStorage.getItem("marker-token");
  return t ? {"Authorization": "Bearer " + t} : {};
}
function needToken() {
  $("login").hidden = false;
  $("message").textContent = "this station needs its token";
}
async function call(method, path) {
  const r = await fetch(path, {method, headers: headers()});
  if (r.status === 401) needToken();
  return r;
}
async function api(method, path) {
  const r = await call(method, path);
  let body = {};
  try { body = await r.json(); } catch (e) {}
  return {ok: r.ok, status: r.status, body};
}
let pictureUrl = null;
async function showPicture() {
  const r = await call("GET", "/api/preview.png");
  if (!r.ok) return;
  if (pictureUrl) URL.revokeObjectURL(pictureUrl);
  pictureUrl = URL.createObjectURL(await r.blob());
  $("picture").src = pictureUrl;
}
function showPart(p) {
  if (!p) return;
  $("last_id").textContent = p.mark_id;
  $("last_outcome").textContent = p.outcome + (p.message ? " (" + p.message + ")" : "");
  $("last_serials").textContent = Object.entries(p.serials || {}).map(([k, v]) => k + " = " + v).join(", ") || "–";
  $("last_time").textContent = p.mark_time_s !== undefined ? p.mark_time_s.toFixed(3) + " s" : "–";
  $("last_text").textContent = p.text;
}
let shownPicture = null;  // the job and text the picture shows
async function refresh() {
  const s = await api("GET", "/api/status");
  if (s.ok) {
    $("state").textContent = s.body.state; $("state").className = s.body.state;
    $("job").textContent = s.body.job;
    $("counts").textContent = s.body.parts + " parts: " +
      Object.entries(s.body.outcomes).map(([k, v]) => v + " " + k).join(", ");
    showPart(s.body.last);
    if (s.body.error) $("message").textContent = "error: " + s.body.error;
  }
  if (s.ok) $("pause").textContent = s.body.state === "paused" ? "Resume" : "Pause";
  if (s.ok && s.body.state !== "marking") {
    const n = await api("GET", "/api/preview");
    $("next").textContent = n.ok ? n.body.text : "(" + n.body.error + ")";
    const drawn = s.body.job + "\n" + (n.ok ? n.body.text : "");
    if (n.ok && drawn !== shownPicture) {
      shownPicture = drawn;
      showPicture();
    }
    const l = await api("GET", "/api/log?limit=50");
    if (l.ok) showLog(l.body);
  }
}
function showLog(rows) {
  const body = $("log").tBodies[0];
  body.textContent = "";
  for (const r of rows.filter(r => r.kind === "mark" || r.kind === "remark").reverse()) {
    const tr = body.insertRow();
    const serials = Object.entries(r.serials || {}).map(([k, v]) => k + "=" + v).join(" ");
    for (const v of [r.id, r.time_utc, r.text, serials, r.outcome || "open"]) tr.insertCell().textContent = v;
  }
}
async function command(path) {
  $("message").textContent = "";
  const r = await api("POST", path);
  if (!r.ok) $("message").textContent = r.body.error || ("HTTP " + r.status);
  refresh();
}
$("mark").onclick = () => command("/api/mark?async=1");
$("abort").onclick = () => command("/api/abort");
$("reset").onclick = () => command("/api/reset");
$("pause").onclick = () => command($("pause").textContent === "Resume" ? "/api/resume" : "/api/pause");
function onEvent(e) {
  $("state").textContent = e.state; $("state").className = e.state;
  if (e.part) showPart(e.part);
  if (e.state !== "marking") refresh();
}
// The server-sent events of /api/events, read as a stream: `data: JSON` blocks separated by a
// blank line, comment lines (": ...") ignored. Reconnects 2 s after the stream ends, unless the
// station wants a token the operator has not given yet (then the login form restarts it).
let listening = false;
async function listen() {
  if (listening) return;
  listening = true;
  try {
    const asked = sessionStorage.getItem("marker-token");
    const r = await call("GET", "/api/events");
    if (r.status === 401) {
      listening = false;
      // A token typed while this request was out (the login's listen() found it listening): again.
      if (sessionStorage.getItem("marker-token") !== asked) listen();
      return;
    }
    if (!r.ok || !r.body) throw new Error("HTTP " + r.status);
    $("message").textContent = "";
    refresh();
    const reader = r.body.getReader();
    const decoder = new TextDecoder();
    let text = "";
    for (;;) {
      const {value, done} = await reader.read();
      if (done) break;
      text += decoder.decode(value, {stream: true});
      for (let end; (end = text.indexOf("\n\n")) >= 0;) {
        const block = text.slice(0, end);
        text = text.slice(end + 2);
        const data = block.split("\n").filter(l => l.startsWith("data: ")).map(l => l.slice(6)).join("\n");
        if (data) onEvent(JSON.parse(data));
      }
    }
  } catch (e) {
    // the station stopped or the network went: reconnect below
  }
  listening = false;
  $("message").textContent = "connection to the station lost; retrying";
  setTimeout(listen, 2000);
}
$("login").onsubmit = ev => {
  ev.preventDefault();
  sessionStorage.setItem("marker-token", $("token").value.trim());
  $("token").value = "";
  $("login").hidden = true;
  $("message").textContent = "";
  listen();
  refresh();
};
listen();
refresh();
</script></body></html>
)html";
  return kPage;
}

}  // namespace mark
