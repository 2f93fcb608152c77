#!/usr/bin/python3
"""Opens a report's index.html in headless Chromium and checks what a reader sees.

Usage: browser_check.py DIR. Drives Chromium through its DevTools protocol (python3-websockets)
and prints one line per problem, exit 1 if there is any:
- every image is loaded and drawn (complete, natural width > 0);
- every link lands: `#id` on an element of the page, a relative file on an existing file;
- no console error, no uncaught exception, no error in the browser's log;
- the rendered text holds no literal Markdown: no backtick, no `**`, no table rule `|---`;
- the page opens with the summary, then the contents (the first two level-2 headings).
Saves a screenshot of the first screen (1280 × 900) as DIR/first-screen.png.
"""
import asyncio
import base64
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.request

import websockets

TIMEOUT = 60  # seconds for the whole check

PAGE_FACTS = r"""
(() => {
  const images = [...document.images].map(i => ({
    src: i.getAttribute('src').slice(0, 60), complete: i.complete, width: i.naturalWidth}));
  const links = [...document.querySelectorAll('a[href]')].map(a => a.getAttribute('href'));
  const ids = [...document.querySelectorAll('[id]')].map(e => e.id);
  const headings = [...document.querySelectorAll('h2')].map(h => h.textContent.trim());
  return JSON.stringify({images, links, ids, headings, text: document.body.innerText});
})()
"""

problems = []


def problem(what):
    problems.append(what)


def start_chromium(profile):
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        sys.exit("FAIL: chromium not found (scripts/install-deps.sh installs it)")
    # --no-sandbox: the sandbox refuses to run as root (CI runs as root).
    return subprocess.Popen(
        [chromium, "--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run",
         "--remote-debugging-port=0", f"--user-data-dir={profile}", "--window-size=1280,900",
         "--hide-scrollbars", "about:blank"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def devtools_port(profile, deadline):
    port_file = os.path.join(profile, "DevToolsActivePort")
    while time.time() < deadline:
        if os.path.exists(port_file):
            lines = open(port_file).read().split("\n")
            if lines and lines[0].strip():
                return int(lines[0])
        time.sleep(0.1)
    sys.exit("FAIL: chromium did not open its DevTools port")


class Session:
    def __init__(self, ws):
        self.ws = ws
        self.next_id = 0
        self.events = []

    async def call(self, method, **params):
        self.next_id += 1
        ident = self.next_id
        await self.ws.send(json.dumps({"id": ident, "method": method, "params": params}))
        while True:
            message = json.loads(await self.ws.recv())
            if message.get("id") == ident:
                if "error" in message:
                    raise RuntimeError(f"{method}: {message['error']}")
                return message.get("result", {})
            self.events.append(message)

    async def wait_for(self, method):
        for e in self.events:
            if e.get("method") == method:
                return e
        while True:
            message = json.loads(await self.ws.recv())
            self.events.append(message)
            if message.get("method") == method:
                return message


def console_errors(events):
    for e in events:
        method, params = e.get("method"), e.get("params", {})
        if method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
            args = " ".join(str(a.get("value", a.get("description", ""))) for a in params["args"])
            problem(f"console error: {args}")
        elif method == "Runtime.exceptionThrown":
            problem(f"uncaught exception: {params['exceptionDetails'].get('text')}")
        elif method == "Log.entryAdded" and params["entry"].get("level") == "error":
            problem(f"browser log error: {params['entry'].get('text')} "
                    f"({params['entry'].get('url', '')[:80]})")


def check_facts(facts, folder):
    for image in facts["images"]:
        if not image["complete"] or image["width"] == 0:
            problem(f"broken image: {image['src']}...")
    ids = set(facts["ids"])
    for href in facts["links"]:
        if href.startswith("#"):
            if href[1:] not in ids:
                problem(f"link {href}: no element with that id")
        elif re.match(r"^(https?:|mailto:|data:)", href):
            continue
        elif not os.path.isfile(os.path.join(folder, href.split("#")[0])):
            problem(f"link {href}: no such file")
    text = facts["text"]
    for pattern, name in ((r"`", "a backtick"), (r"\*\*", "`**`"), (r"\|\s*-{3}", "a table rule")):
        for m in list(re.finditer(pattern, text))[:3]:
            context = text[max(0, m.start() - 40):m.end() + 40].replace("\n", " ")
            problem(f"literal Markdown ({name}) in the rendered text: ...{context}...")
    if facts["headings"][:2] != ["Summary", "Contents"]:
        problem(f"the page does not open with the summary and the contents: "
                f"{facts['headings'][:2]}")


async def check(folder, port, deadline):
    with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list") as r:
        pages = [t for t in json.load(r) if t["type"] == "page"]
    async with websockets.connect(pages[0]["webSocketDebuggerUrl"], max_size=None) as ws:
        s = Session(ws)
        for domain in ("Page", "Runtime", "Log"):
            await s.call(f"{domain}.enable")
        await s.call("Emulation.setDeviceMetricsOverride", width=1280, height=900,
                     deviceScaleFactor=1, mobile=False)
        s.events.clear()
        url = "file://" + os.path.abspath(os.path.join(folder, "index.html"))
        await s.call("Page.navigate", url=url)
        await asyncio.wait_for(s.wait_for("Page.loadEventFired"), deadline - time.time())
        result = await s.call("Runtime.evaluate", expression=PAGE_FACTS, returnByValue=True)
        facts = json.loads(result["result"]["value"])
        shot = await s.call("Page.captureScreenshot", format="png")
        with open(os.path.join(folder, "first-screen.png"), "wb") as f:
            f.write(base64.b64decode(shot["data"]))
        console_errors(s.events)
        check_facts(facts, folder)
        return facts


def main():
    folder = sys.argv[1]
    if not os.path.isfile(os.path.join(folder, "index.html")):
        sys.exit(f"FAIL: {folder}/index.html does not exist")
    start = time.time()
    deadline = start + TIMEOUT
    profile = tempfile.mkdtemp(prefix="rotbeam-chromium-")
    browser = start_chromium(profile)
    try:
        port = devtools_port(profile, deadline)
        facts = asyncio.run(asyncio.wait_for(check(folder, port, deadline), TIMEOUT))
    finally:
        browser.terminate()
        try:
            browser.wait(10)
        except subprocess.TimeoutExpired:
            browser.kill()
        shutil.rmtree(profile, ignore_errors=True)
    for p in problems:
        print("FAIL: " + p)
    print(f"browser check {folder}: {len(facts['images'])} images, {len(facts['links'])} links, "
          f"{len(facts['text'])} characters of text, {time.time() - start:.1f} s: "
          + (f"{len(problems)} problems" if problems else "all passed"))
    sys.exit(1 if problems else 0)


main()
