#!/usr/bin/python3
"""browser.py - a rendered page (build/paper.html) as a reader's browser shows it.

Drives Debian's Chromium, headless, over the DevTools protocol (a websocket: Debian's
python3-websocket; nothing downloaded, no network but the loopback), and checks each PAGE at a
phone's width (390 px) and a laptop's (1366 px):
  placeholders  no raw placeholder of tools/lib/paper-filter.lua left in the text or as an HTML
                comment: {{...}}, <!-- summary-table -->, <!-- figure: ... --> and the other block
                kinds, and the quick tier's old in-sentence mark "(quick tier: run `make figures`)"
  images        every <img> loaded (complete, naturalWidth > 0)
  links         every internal link (href="#id") names an element of the page
  tables        no table reaches past the page: a table, or the scrolling box it sits in
                (overflow-x auto or scroll), lies within the viewport, and the page itself
                does not scroll sideways (its scrollWidth is the viewport's)
Prints one line per check and width, "PASS|FAIL PAGE@WIDTH: CHECK: detail"; exit 1 if any failed.

usage: tests/browser.py [--shots DIR] [--section EXP] PAGE...
       tests/browser.py --self-test DIR
--shots DIR: screenshots of the first PAGE into DIR: paper-summary.png (the section "Summary" at
  1366 px), paper-summary-phone.png (its top at 390 px) and paper-section.png (the section whose
  heading starts with EXP at 1366 px; default phan-thien-2016/fig08-compressibility).
--self-test DIR: every DIR/*.html: pass.html must pass every check; fail-CHECK[-anything].html must
  fail CHECK at some width and pass every other check (that each check can fail).
env: CHROMIUM (default: chromium, else chromium-browser, on PATH)
"""
import base64, json, os, re, shutil, subprocess, sys, tempfile, threading, time

try:
    import websocket   # Debian: python3-websocket (tools/deps browser)
except ImportError:
    sys.exit("browser.py: no python3 module 'websocket' (Debian: python3-websocket; tools/deps browser)")

WIDTHS = [(390, 844, True), (1366, 768, False)]
CHECKS = ["placeholders", "images", "links", "tables"]
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-extensions", "--hide-scrollbars", "--mute-audio", "--remote-debugging-port=0"]

# run in the page: every check at the current width; returns {check: [ok, detail]}
CHECK_JS = r"""
(async () => {
  await new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)));
  const out = {};
  const short = s => s.length > 80 ? s.slice(0, 77) + '...' : s;
  // placeholders: in the text, and as comments (a block placeholder left unfilled stays a comment)
  const kinds = /^\s*(summary-table|environment|results:|figure:|tsv:|table:)/;
  const found = [];
  const text = document.body.innerText;
  for (const m of text.matchAll(/\{\{[^}\n]{0,120}\}\}|<!--[^\n]{0,80}|\(quick tier: run `?make figures`?\)/g)) found.push(m[0]);
  const walker = document.createTreeWalker(document.documentElement, NodeFilter.SHOW_COMMENT);
  for (let c; (c = walker.nextNode());) if (kinds.test(c.data)) found.push('<!--' + c.data + '-->');
  out.placeholders = [found.length === 0, found.length ? found.length + ' left, e.g. ' + found.slice(0, 3).map(short).join(' | ') : 'none left'];
  // images
  const imgs = Array.from(document.images);
  await Promise.all(imgs.map(i => i.complete ? null : new Promise(r => { i.onload = i.onerror = r; setTimeout(r, 10000); })));
  const broken = imgs.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => short(i.getAttribute('src') || '(no src)'));
  out.images = [broken.length === 0, broken.length ? broken.length + ' of ' + imgs.length + ' do not load: ' + broken.slice(0, 3).join(' | ') : imgs.length + ' loaded'];
  // internal links
  const links = Array.from(document.querySelectorAll('a[href^="#"]'));
  const dead = links.map(a => a.getAttribute('href')).filter(h => {
    let id; try { id = decodeURIComponent(h.slice(1)); } catch (e) { return true; }
    return id === '' || !(document.getElementById(id) || document.getElementsByName(id).length);
  });
  out.links = [dead.length === 0, dead.length ? dead.length + ' of ' + links.length + ' lead nowhere: ' + dead.slice(0, 5).join(' ') : links.length + ' resolve'];
  // tables: each, or the scrolling box around it, within the viewport; the page not wider than it
  const vw = document.documentElement.clientWidth;
  const wide = [];
  for (const t of document.querySelectorAll('table')) {
    let box = t;
    for (let p = t.parentElement; p && p !== document.body; p = p.parentElement) {
      const ox = getComputedStyle(p).overflowX;
      if (ox === 'auto' || ox === 'scroll') { box = p; break; }
    }
    const r = box.getBoundingClientRect();
    if (r.right > vw + 0.5 || r.left < -0.5) {
      const h = t.closest('section, body') && (t.querySelector('th, td') || t).innerText;
      wide.push(Math.round(r.width) + ' px (' + short((h || '').replace(/\s+/g, ' ')) + ')');
    }
  }
  const sw = document.documentElement.scrollWidth;
  const page = sw > vw + 0.5 ? ['the page scrolls sideways: ' + sw + ' px wide in ' + vw] : [];
  const bad = wide.concat(page);
  out.tables = [bad.length === 0, bad.length ? bad.slice(0, 4).join('; ') + (bad.length > 4 ? ' ...' : '')
                 : document.querySelectorAll('table').length + ' tables within ' + vw + ' px'];
  return JSON.stringify(out);
})()
"""

# the rectangle (page coordinates) of the section whose heading's text starts with PREFIX: from
# that heading to the next heading of its level or above, at most MAXH px
SECTION_JS = r"""
((prefix, maxh) => {
  const hs = Array.from(document.querySelectorAll('h1, h2, h3'));
  const i = hs.findIndex(h => h.textContent.trim().startsWith(prefix));
  if (i < 0) return JSON.stringify(null);
  const h = hs[i], lv = +h.tagName[1];
  const next = hs.slice(i + 1).find(n => +n.tagName[1] <= lv);
  const y0 = h.getBoundingClientRect().top + scrollY - 8;
  const y1 = next ? next.getBoundingClientRect().top + scrollY - 8 : document.documentElement.scrollHeight;
  const w = document.documentElement.clientWidth;
  return JSON.stringify({x: 0, y: Math.max(0, y0), width: w, height: Math.min(maxh, y1 - y0), full: y1 - y0});
})
"""


class Browser:
    def __init__(self):
        exe = os.environ.get("CHROMIUM") or shutil.which("chromium") or shutil.which("chromium-browser")
        if not exe:
            sys.exit("browser.py: no chromium (Debian: chromium; tools/deps browser)")
        self.profile = tempfile.mkdtemp(prefix="dpd-chromium-")
        self.proc = subprocess.Popen([exe] + FLAGS + ["--user-data-dir=" + self.profile, "about:blank"],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        url, deadline, seen = None, time.time() + 60, []
        while time.time() < deadline:
            line = self.proc.stderr.readline()
            if not line:
                break
            seen.append(line.strip())
            m = re.search(r"DevTools listening on (ws://\S+)", line)
            if m:
                url = m.group(1)
                break
        if not url:
            self.close()
            sys.exit("browser.py: chromium did not start its DevTools endpoint: " + " / ".join(seen[-5:]))
        # the rest of chromium's stderr is read and dropped (a full pipe would stall it)
        threading.Thread(target=lambda: [None for _ in self.proc.stderr], daemon=True).start()
        self.ws = websocket.create_connection(url, timeout=120, suppress_origin=True)
        self.id, self.events = 0, []
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        self.call("Page.enable", session=True)
        self.call("Runtime.enable", session=True)

    def call(self, method, params=None, session=False):
        self.id += 1
        msg = {"id": self.id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = self.session
        self.ws.send(json.dumps(msg))
        while True:
            r = json.loads(self.ws.recv())
            if r.get("id") == self.id:
                if "error" in r:
                    raise RuntimeError(f"{method}: {r['error'].get('message')}")
                return r.get("result", {})
            if "method" in r:
                self.events.append(r["method"])

    def wait_event(self, name, timeout=120):
        deadline = time.time() + timeout
        while name not in self.events:
            if time.time() > deadline:
                raise RuntimeError(f"no {name} within {timeout} s")
            r = json.loads(self.ws.recv())
            if "method" in r:
                self.events.append(r["method"])
        self.events.remove(name)

    def width(self, w, h, mobile):
        self.call("Emulation.setDeviceMetricsOverride",
                  {"width": w, "height": h, "deviceScaleFactor": 1, "mobile": mobile}, session=True)

    def load(self, path):
        self.events = []
        self.call("Page.navigate", {"url": "file://" + os.path.abspath(path)}, session=True)
        self.wait_event("Page.loadEventFired")

    def evaluate(self, js):
        r = self.call("Runtime.evaluate", {"expression": js, "awaitPromise": True, "returnByValue": True},
                      session=True)
        if "exceptionDetails" in r:
            raise RuntimeError("page script: " + json.dumps(r["exceptionDetails"])[:300])
        return json.loads(r["result"]["value"])

    def shot(self, path, clip):
        r = self.call("Page.captureScreenshot", {"format": "png", "captureBeyondViewport": True,
                                                 "clip": dict(clip, scale=1)}, session=True)
        with open(path, "wb") as f:
            f.write(base64.b64decode(r["data"]))

    def close(self):
        try:
            self.ws.close()
        except Exception:
            pass
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
        shutil.rmtree(self.profile, ignore_errors=True)


def check_page(b, page):
    """{(check, width): (ok, detail)} for PAGE at every width"""
    res = {}
    b.width(*WIDTHS[0])
    b.load(page)
    for w, h, mobile in WIDTHS:
        b.width(w, h, mobile)
        for name, (ok, detail) in b.evaluate(CHECK_JS).items():
            res[(name, w)] = (ok, detail)
    return res


def screenshots(b, page, outdir, section):
    os.makedirs(outdir, exist_ok=True)
    made = []
    for (w, h, mobile), prefix, name, maxh in [(WIDTHS[1], "Summary", "paper-summary.png", 4000),
                                             (WIDTHS[0], "Summary", "paper-summary-phone.png", 2400),
                                             (WIDTHS[1], section, "paper-section.png", 5000)]:
        b.width(w, h, mobile)
        clip = b.evaluate(SECTION_JS + f"({json.dumps(prefix)}, {maxh})")
        if not clip:
            print(f"FAIL screenshot {name}: no heading starting with '{prefix}'")
            return False
        full = clip.pop("full")
        b.shot(os.path.join(outdir, name), clip)
        made.append(f"{os.path.join(outdir, name)} ({clip['width']}x{round(clip['height'])} of {round(full)} px)")
    print("screenshots: " + "; ".join(made))
    return True


def report(page, res):
    nfail = 0
    for (name, w), (ok, detail) in sorted(res.items(), key=lambda kv: (CHECKS.index(kv[0][0]), kv[0][1])):
        print(f"{'PASS' if ok else 'FAIL'} {os.path.basename(page)}@{w}: {name}: {detail}")
        nfail += not ok
    return nfail


def self_test(b, d):
    """every fixture fails exactly the check its name says (pass.html: none)"""
    files = sorted(f for f in os.listdir(d) if f.endswith(".html"))
    npass = nfail = 0
    for f in files:
        m = re.match(r"fail-([a-z]+)", f)
        want = m.group(1) if m else None
        if f != "pass.html" and want not in CHECKS:
            print(f"FAIL self-test {f}: name it pass.html or fail-CHECK.html, CHECK one of {', '.join(CHECKS)}")
            nfail += 1
            continue
        res = check_page(b, os.path.join(d, f))
        failed = sorted({c for (c, _), (ok, _) in res.items() if not ok})
        ok = failed == ([want] if want else [])
        detail = "; ".join(f"{c}@{w}: {det}" for (c, w), (o, det) in sorted(res.items()) if not o) or "every check passes"
        print(f"{'PASS' if ok else 'FAIL'} self-test {f}: "
              + (f"fails {want} only" if want else "passes every check") + ("" if ok else f": failed {failed}")
              + f" ({detail})")
        npass += ok
        nfail += not ok
    if not files:
        print(f"FAIL self-test: no fixtures in {d}")
        nfail += 1
    return npass, nfail


def main(argv):
    shots, section, selftest, pages = None, "phan-thien-2016/fig08-compressibility", None, []
    it = iter(argv)
    for a in it:
        if a == "--shots":
            shots = next(it)
        elif a == "--section":
            section = next(it)
        elif a == "--self-test":
            selftest = next(it)
        elif a in ("-h", "--help"):
            print(__doc__)
            return 0
        else:
            pages.append(a)
    if not pages and not selftest:
        print(__doc__, file=sys.stderr)
        return 2
    for p in pages:
        if not os.path.isfile(p):
            print(f"browser.py: no page {p} (make paper)", file=sys.stderr)
            return 2
    b = Browser()
    try:
        if selftest:
            npass, nfail = self_test(b, selftest)
            print(f"{npass} passed, {nfail} failed")
            return 1 if nfail else 0
        nfail = npass = 0
        for p in pages:
            res = check_page(b, p)
            f = report(p, res)
            nfail += f
            npass += len(res) - f
        if shots and not screenshots(b, pages[0], shots, section):
            nfail += 1
        print(f"{npass} passed, {nfail} failed")
        return 1 if nfail else 0
    finally:
        b.close()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
