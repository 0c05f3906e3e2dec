// The fleet page: every gateway on the broker and its ports, from /fleet.json and again each
// time /events sends a new snapshot. Every value is set as text, never as HTML.
"use strict";

(() => {
  const number = new Intl.NumberFormat("en-US");
  const $ = (id) => document.getElementById(id);
  const SENDING = ["waiting", "sending", "paused"];

  function cell(row, text, className) {
    const td = document.createElement("td");
    td.textContent = text;
    if (className) td.className = className;
    row.appendChild(td);
    return td;
  }

  function badge(td, state, words) {
    const b = document.createElement("span");
    b.className = `badge ${state}`;
    b.textContent = words;
    td.appendChild(b);
  }

  function moment(iso) {
    if (!iso) return "\u2014";
    const t = new Date(iso);
    return Number.isNaN(t.getTime()) ? iso : t.toLocaleString();
  }

  function gatewayRow(g) {
    const row = document.createElement("tr");
    row.dataset.gateway = g.name;
    cell(row, g.name, "name");
    // online: "idle" colours; offline: the offline badge; unknown: no port state yet
    badge(cell(row, "", "state"), g.state === "online" ? "idle" : "offline",
      g.state + (g.state !== "online" && g.reason ? ` (${g.reason})` : ""));
    cell(row, moment(g.since), "when");
    cell(row, number.format(g.ports.length), "num");
    cell(row, number.format(g.queued || 0), "num");
    cell(row, number.format(g.dropped || 0), g.dropped ? "num bad" : "num");
    return row;
  }

  function portRow(g, p) {
    const row = document.createElement("tr");
    row.dataset.port = `${g.name}/${p.name}`;
    cell(row, g.name, "name");
    cell(row, String(p.index), "num");
    const name = cell(row, p.name, "name");
    const profile = document.createElement("span");
    profile.className = "profile";
    profile.textContent = p.profile || "";
    name.appendChild(profile);
    // an offline gateway's ports show their last known state, greyed
    badge(cell(row, "", "state"), g.state === "online" ? p.state : "stopped",
      g.state === "online" ? p.state_words : `(${p.state_words})`);
    cell(row, p.program || "\u2014", "program");
    const progress = cell(row, "", "progress");
    if (SENDING.includes(p.state) && p.progress !== null && p.progress !== undefined) {
      const bar = document.createElement("div");
      bar.className = "bar";
      const fill = document.createElement("div");
      fill.className = "fill";
      fill.style.width = `${(p.progress * 100).toFixed(1)}%`;
      bar.appendChild(fill);
      const label = document.createElement("span");
      label.textContent = `${Math.floor(p.progress * 100)} %`;
      progress.append(bar, label);
    }
    cell(row, number.format(p.errors || 0), p.errors ? "errors num bad" : "errors num");
    cell(row, number.format(p.data_lines || 0), "num");
    const result = p.result || "none";
    cell(row, result === "none" ? "\u2014" : result, `result r-${result.replace(/ /g, "-")}`);
    cell(row, p.message || "", "message");
    return row;
  }

  function render(s) {
    $("broker").textContent = s.broker;
    $("gateways").tBodies[0].replaceChildren(...s.gateways.map(gatewayRow));
    $("no-gateways").hidden = s.gateways.length > 0;
    $("ports").tBodies[0].replaceChildren(
      ...s.gateways.flatMap((g) => g.ports.map((p) => portRow(g, p))));
    document.body.dataset.updated = s.time;
  }

  function live(up, text) {
    const el = $("live");
    el.className = up ? "live up" : "live down";
    el.textContent = text;
  }

  function show(s) {
    render(s);
    live(true, "live");
  }

  fetch("fleet.json", { cache: "no-store" }).then((r) => r.json()).then(show)
    .catch(() => live(false, "no answer"));
  if (window.EventSource) {
    const events = new EventSource("events");
    events.onmessage = (e) => show(JSON.parse(e.data));
    events.onerror = () => live(false, "reconnecting\u2026");
  }
})();
