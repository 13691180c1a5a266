#!/usr/bin/env python3
"""Reference test: renders the cases of three_vrm_cases.py in Inkshade and in three-vrm 3.5.5 on
three.js r187 (the pinned packages in tests/reference/node_modules, Debian's headless Chromium with
SwiftShader's WebGL 2) and compares the pictures pixel by pixel (docs/testing.md#reference-test).

    tests/reference/three_vrm_parity.py --inkshade build/inkshade --out build/reference/three_vrm

A pixel is the object's when it is not background (alpha 0) on either side; it is off when a
channel differs by more than 3/255 (or only one side covers it). A case passes when at most
0.5 % of its object pixels are off. Both pictures and a diff picture per case land in --out.
Python's standard library only."""
import argparse
import concurrent.futures
import http.server
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import urllib.parse

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png_file  # noqa: E402
import three_vrm_cases  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
MODULES = os.path.join(HERE, "node_modules")
NEEDED = ["three/build/three.module.js", "three/examples/jsm/loaders/GLTFLoader.js",
          "@pixiv/three-vrm/lib/three-vrm.module.js"]
TOLERANCE = 3  # levels of 255 a channel may differ by
PASS_FRACTION = 0.005  # of the object pixels that may be off
# Inkshade draws a VRM's MToon materials as three-vrm does with the file's camera and light.
INKSHADE_VRM = ["--camera", "0", "--lights", "file"]
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                  "--disable-quic", "--no-first-run", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage",
                  "--disable-extensions", "--mute-audio"]


def fail(message):
    print("reference.three_vrm: " + message, file=sys.stderr)
    sys.exit(1)


def find_chromium():
    for name in ("chromium", "chromium-browser"):
        path = shutil.which(name)
        if path:
            return path
    return None


class Results:
    """What the page posted: RGBA rows (top first) per case, and how it ended."""

    def __init__(self):
        self.images, self.done, self.error, self.log = {}, threading.Event(), None, ""


def make_handler(cases_dir, cases_json, results, ready):
    files = {"/": os.path.join(HERE, "three_vrm_page.html"),
             "/three_vrm_render.js": os.path.join(HERE, "three_vrm_render.js")}
    types = {".html": "text/html", ".js": "text/javascript", ".json": "application/json"}

    class Handler(http.server.BaseHTTPRequestHandler):
        def log_message(self, *args):
            pass

        def reply(self, code, body=b"", kind="text/plain"):
            self.send_response(code)
            self.send_header("Content-Type", kind)
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)

        def do_GET(self):
            path = urllib.parse.urlparse(self.path).path
            if path == "/cases.json":
                ready.wait()  # Chromium starts while the cases are written
                return self.reply(200, cases_json, "application/json")
            if path in files:
                name = files[path]
            elif path.startswith("/node_modules/"):
                name = os.path.join(MODULES, path[len("/node_modules/"):])
            elif path.startswith("/cases/"):
                name = os.path.join(cases_dir, path[len("/cases/"):])
            else:
                return self.reply(404)
            name = os.path.realpath(name)
            if ".." in path or not os.path.isfile(name):
                return self.reply(404)
            with open(name, "rb") as f:
                self.reply(200, f.read(), types.get(os.path.splitext(name)[1], "application/octet-stream"))

        def do_POST(self):
            url = urllib.parse.urlparse(self.path)
            body = self.rfile.read(int(self.headers.get("Content-Length", 0)))
            if url.path == "/result":
                q = urllib.parse.parse_qs(url.query)
                w, h = int(q["width"][0]), int(q["height"][0])
                rows = [body[y * w * 4:(y + 1) * w * 4] for y in range(h)]
                results.images[q["name"][0]] = (w, h, b"".join(reversed(rows)))
            elif url.path == "/done":
                results.log = body.decode(errors="replace")
                results.done.set()
            elif url.path == "/fail":
                results.error = body.decode(errors="replace")
                results.done.set()
            self.reply(200)

    return Handler


def render_reference(chromium, cases_dir, cases, out, timeout, ready):
    """Renders every case in one Chromium, which asks for them once `ready` is set; returns Results."""
    results = Results()
    listing = json.dumps([{k: c[k] for k in ("name", "kind", "file", "size")} for c in cases]).encode()
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), make_handler(cases_dir, listing, results, ready))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    profile = tempfile.mkdtemp(prefix="inkshade-chromium-")
    log = open(os.path.join(out, "chromium.log"), "wb")
    url = "http://127.0.0.1:%d/" % server.server_address[1]
    browser = subprocess.Popen([chromium] + CHROMIUM_FLAGS + ["--user-data-dir=" + profile, url],
                               stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + timeout
        while not results.done.wait(0.25):
            if browser.poll() is not None:
                results.error = "Chromium exited (status %d) before the page was done; see %s" % (browser.returncode, log.name)
                break
            if time.monotonic() > deadline:
                results.error = "Chromium gave no answer in %d s; see %s" % (timeout, log.name)
                break
    finally:
        browser.terminate()
        try:
            browser.wait(10)
        except subprocess.TimeoutExpired:
            browser.kill()
            browser.wait()
        server.shutdown()
        log.close()
        shutil.rmtree(profile, ignore_errors=True)
    return results


def inkshade_command(inkshade, case, cases_dir, target):
    w, h = case["size"]
    common = ["--samples", "1", "--size", "%dx%d" % (w, h), "--background", "transparent", "-o", target]
    source = os.path.join(cases_dir, case["file"])
    if case["kind"] == "scene":
        return [inkshade, "render", "--scene", source] + common
    return [inkshade, "render", source] + INKSHADE_VRM + common


def render_inkshade(args, cases, cases_dir):
    """Runs the Inkshade renders two at a time; returns {name: error message or None}."""
    def one(case):
        target = os.path.join(args.out, case["name"] + ".inkshade.png")
        command = inkshade_command(args.inkshade, case, cases_dir, target)
        run = subprocess.run(command, capture_output=True, text=True)
        return case["name"], (run.stderr.strip() or "exit %d" % run.returncode) if run.returncode else None
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        return dict(pool.map(one, cases))


def compare(ours, theirs):
    """(object pixels, off pixels, max channel difference where both cover, diff RGBA)."""
    (w, h, a), (_, _, b) = ours, theirs
    objects = off = worst = 0
    diff = bytearray(w * h * 4)
    for i in range(0, w * h * 4, 4):
        ca, cb = a[i + 3] > 0, b[i + 3] > 0
        if not (ca or cb):
            continue
        objects += 1
        diff[i + 3] = 255
        if ca != cb:
            off += 1
            diff[i:i + 3] = b"\xff\xff\x00" if ca else b"\x00\xc0\xff"  # yellow: only ours, blue: only theirs
            continue
        d = max(abs(a[i] - b[i]), abs(a[i + 1] - b[i + 1]), abs(a[i + 2] - b[i + 2]))
        worst = max(worst, d)
        if d > TOLERANCE:
            off += 1
            diff[i:i + 3] = bytes((min(255, 64 + 8 * d), 0, 0))
        else:
            g = (a[i] + a[i + 1] + a[i + 2]) // 12  # the picture, dim, where it matches
            diff[i:i + 3] = bytes((g, g, g))
    return objects, off, worst, diff


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--inkshade", required=True)
    parser.add_argument("--out", required=True, help="folder for the cases' files and pictures")
    parser.add_argument("--timeout", type=int, default=50, help="seconds Chromium may take for all cases")
    parser.add_argument("--only", help="comma-separated case names")
    return parser.parse_args()


def render_both(args, chromium, cases):
    """Writes the cases, renders them on both sides at once; returns (Inkshade errors, Results)."""
    cases_dir = os.path.join(args.out, "cases")
    os.makedirs(cases_dir, exist_ok=True)
    ready = threading.Event()
    with concurrent.futures.ThreadPoolExecutor(1) as pool:
        reference = pool.submit(render_reference, chromium, cases_dir, cases, args.out, args.timeout, ready)
        try:
            for c in cases:
                c["write"](cases_dir)
        finally:
            ready.set()
        errors = render_inkshade(args, cases, cases_dir)
        return errors, reference.result()


def judge(out, name, error, reference):
    """(table line, whether the case is within the tolerance); writes the pictures."""
    if error:
        return "%-28s inkshade failed: %s" % (name, error.splitlines()[-1]), False
    if reference is None:
        return "%-28s three-vrm drew nothing" % name, False
    w, h, pixels = reference
    png_file.write(os.path.join(out, name + ".three-vrm.png"), w, h, pixels)
    ours = png_file.read_rgba(os.path.join(out, name + ".inkshade.png"))
    if ours[:2] != (w, h):
        return "%-28s sizes differ: %dx%d vs %dx%d" % (name, ours[0], ours[1], w, h), False
    objects, off, worst, diff = compare(ours, (w, h, pixels))
    png_file.write(os.path.join(out, name + ".diff.png"), w, h, diff)
    share = off / objects if objects else 1.0
    return "%-28s %9d %7.2f%% %6d" % (name, objects, 100 * share, worst), share <= PASS_FRACTION


def main():
    args = parse_args()
    missing = [p for p in NEEDED if not os.path.isfile(os.path.join(MODULES, p))]
    chromium = find_chromium()
    if missing or not chromium:
        fail("%s missing; run scripts/setup" % ("Chromium" if not chromium else "tests/reference/node_modules/" + missing[0]))
    cases = three_vrm_cases.CASES
    if args.only:
        cases = [c for c in cases if c["name"] in args.only.split(",")]
    os.makedirs(args.out, exist_ok=True)
    start = time.monotonic()
    errors, theirs = render_both(args, chromium, cases)
    if theirs.error:
        fail("three-vrm page: " + (theirs.error.strip().splitlines() or ["failed"])[0])

    print("%-28s %9s %8s %6s" % ("case", "object px", "% off", "max"))
    failed, pending = [], three_vrm_cases.PENDING
    for c in cases:
        line, ok = judge(args.out, c["name"], errors.get(c["name"]), theirs.images.get(c["name"]))
        if c["name"] in pending:
            # A known difference waits for its fix; once fixed, the case must leave PENDING.
            line += "  pending: " + pending[c["name"]] if not ok else "  PASSES: remove it from PENDING"
            ok = not ok
        print(line if ok else line + ("" if "PENDING" in line else "  FAIL"))
        if not ok:
            failed.append(c["name"])
    print("%d of %d cases as expected (within %d/255 on all but %.1f %% of their pixels, or pending); "
          "%.1f s; pictures in %s" % (len(cases) - len(failed), len(cases), TOLERANCE, 100 * PASS_FRACTION,
                                      time.monotonic() - start, args.out))
    if theirs.log.strip():
        print("three-vrm console errors:\n" + theirs.log)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
