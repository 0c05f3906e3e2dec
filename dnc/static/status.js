// The gateway's status page: renders the snapshot of /status.json, and again each time
// /events (server-sent events) sends a new one. Every value is set as text, never as HTML:
// program names and error messages come from what controls punched.
"use strict";

(() => {
  const number = new Intl.NumberFormat("en-US");
  const $ = (id) => document.getElementById(id);

  function cell(row, text, className) {
    const td = document.createElement("td");
    td.textContent = text;
    if (className) td.className = className;
    row.appendChild(td);
    return td;
  }

  function moment(iso) {
    if (!iso) return "now";
    const t = new Date(iso);
    if (Number.isNaN(t.getTime())) return iso;
    const pad = (n) => String(n).padStart(2, "0");
    const time = `${pad(t.getHours())}:${pad(t.getMinutes())}:${pad(t.getSeconds())}`;
    const today = new Date().toDateString() === t.toDateString();
    return today ? time
      : `${t.getFullYear()}-${pad(t.getMonth() + 1)}-${pad(t.getDate())} ${time}`;
  }

  const SENDING = ["waiting", "sending", "paused"];

  function portRow(p) {
    const row = document.createElement("tr");
    row.dataset.port = p.name;
    row.dataset.state = p.state;
    cell(row, String(p.index), "num");
    const name = cell(row, p.name, "name");
    name.title = p.url;
    const profile = document.createElement("span");
    profile.className = "profile";
    profile.textContent = p.profile;
    name.appendChild(profile);
    const state = cell(row, "", "state");
    const badge = document.createElement("span");
    badge.className = `badge ${p.state}`;
    badge.textContent = p.state_words;
    state.appendChild(badge);
    cell(row, p.program || "\u2014", "program");
    const sending = SENDING.includes(p.state);
    cell(row, sending && p.line ? `line ${number.format(p.line)}` : "\u2014", "block");
    const bytes = sending
      ? `${number.format(p.bytes_sent)} / ${number.format(p.bytes_total)}` : "\u2014";
    cell(row, bytes, "bytes num");
    const progress = cell(row, "", "progress");
    if (sending && p.progress !== null) {
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
    cell(row, number.format(p.errors), p.errors ? "errors num bad" : "errors num");
    // machine data lines (DPRNT) counted since the service started; the last one as a tooltip
    const data = cell(row, p.data_lines ? number.format(p.data_lines) : "\u2014", "data num");
    data.title = p.data_last || "";
    cell(row, p.result === "none" ? "\u2014" : p.result, `result r-${p.result.replace(/ /g, "-")}`);
    // while the program goes out, the last event is still "waiting for DC1": the state says more
    cell(row, p.state === "sending" || p.state === "paused" ? "" : p.message, "message");
    return row;
  }

  function errorItem(e) {
    const li = document.createElement("li");
    const head = document.createElement("div");
    head.className = "head";
    const when = document.createElement("span");
    when.className = "when";
    when.textContent = moment(e.time);
    const what = document.createElement("strong");
    what.textContent = [e.port, e.result, e.program].filter(Boolean).join(" \u00b7 ");
    head.append(when, what);
    li.appendChild(head);
    for (const text of e.errors) {
      const line = document.createElement("div");
      line.className = "detail";
      line.textContent = text;
      li.appendChild(line);
    }
    if (e.more) {
      const more = document.createElement("div");
      more.className = "detail quiet";
      more.textContent = `\u2026 and ${e.more} more (tapegate journal)`;
      li.appendChild(more);
    }
    return li;
  }

  function transferRow(t) {
    const row = document.createElement("tr");
    cell(row, moment(t.end), "when");
    cell(row, t.port);
    cell(row, t.direction);
    cell(row, t.program || "\u2014", "program");
    cell(row, number.format(t.bytes), "num");
    cell(row, number.format(t.blocks), "num");
    const n = t.errors.length;
    const errors = n ? ` (${n} ${n === 1 ? "error" : "errors"})` : "";
    cell(row, t.result + errors, `result r-${t.result.replace(/ /g, "-")}`);
    return row;
  }

  function render(s) {
    $("ports").tBodies[0].replaceChildren(...s.ports.map(portRow));
    $("errors").replaceChildren(...s.errors.map(errorItem));
    $("no-errors").hidden = s.errors.length > 0;
    $("transfers").tBodies[0].replaceChildren(...s.transfers.map(transferRow));
    $("no-transfers").hidden = s.transfers.length > 0;
    $("no-transfers").textContent = s.journal ? "None yet." : "No journal configured.";
    document.body.dataset.updated = s.time;
  }

  function live(up, text) {
    const el = $("live");
    el.className = up ? "live up" : "live down";
    el.textContent = text;
  }

  function show(s) {
    render(s);
    live(true, `live \u00b7 ${moment(s.time)}`);
  }

  function poll() {  // where there is no EventSource
    fetch("status.json", { cache: "no-store" })
      .then((r) => r.json()).then(show)
      .catch(() => live(false, "no answer from the gateway"))
      .finally(() => setTimeout(poll, 1000));
  }

  if (!window.EventSource) {
    poll();
    return;
  }
  fetch("status.json", { cache: "no-store" }).then((r) => r.json()).then(show)
    .catch(() => live(false, "no answer from the gateway"));
  const events = new EventSource("events");
  events.onmessage = (e) => show(JSON.parse(e.data));
  // the browser connects again by itself (after the "retry" the server gave)
  events.onerror = () => live(false, "reconnecting\u2026");
})();
