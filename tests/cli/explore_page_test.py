#!/usr/bin/env python3
"""tests/cli/explore_page_test.py: the explorer page of `qm-atms explore` (docs/EXPLORER.md) in a
real browser: Debian's Chromium, headless, driven by chromedriver through Selenium.

Checks, on the bundled escapement:
  - the page loads from a file:// URL with the browser's network off, fetches nothing but its own
    files, and logs no console error;
  - its data agrees with `qm-atms --places --json` (the same place ids, kinds and points);
  - selecting a place (from the list, by clicking its number, by following an adjacency) moves the
    drawn parts to that place's sample configuration, computed here from the --places JSON by the
    rule of geometry/place_sample.hpp, and shows as many contact marks as the data says (at least
    one at a CSEG); pointing at a place shows it, and leaving it shows the selected one again;
  - the page's envisionment is `qm-atms envision --json`'s; its graph shows at most 150 states at a
    time (the escapement has more, and the page says so); selecting a state shows its next and
    previous states (those of the transitions), the parts at its places' samples with one arrow per
    moving part pointing its way, and its point in the configuration space; following a next state
    selects it;
  - a history typed in plays state by state (each of its states shown in turn, the point's trail
    growing), `...` finds the shortest path, a step with no transition is refused, and the
    described behaviour of `explore --path` (`envision --path`'s answer) steps through its states;
  - screenshots at two window sizes have non-blank configuration-space, drawing, graph and state
    areas.

Usage: explore_page_test.py QM_ATMS SOURCE_DIR WORK_DIR. Exit 0 pass, 1 fail, 77 skipped (ctest's
SKIP_RETURN_CODE) only when chromium, chromedriver or Python's Selenium is not installed
(cmake/install-deps.sh installs them).
"""
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import zlib

SKIP = 77
SCENE = "scenarios/metric/escapement.def"
DESCRIBED = "scape-wheel/pallets:free ; scape-wheel/pallets:contact ; scape-wheel/pallets:free"
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage"]


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)


def png_pixels(data):
    """Width, height and rows of (r, g, b) of an 8-bit RGB or RGBA PNG (what Chromium writes)."""
    check(data[:8] == b"\x89PNG\r\n\x1a\n", "a screenshot is not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour = header[0], header[1], header[2], header[3]
    check(depth == 8 and colour in (2, 6), "unexpected PNG format %d/%d" % (depth, colour))
    step = 4 if colour == 6 else 3
    raw, stride, rows, prev = zlib.decompress(idat), width * step, [], bytearray(width * step)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - step] if i >= step else 0
            b, c = prev[i], prev[i - step] if i >= step else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * step:x * step + 3]) for x in range(width)])
        prev = line
    return width, height, rows


def inked(png):
    """The share of pixels that are not white or nearly (anti-aliasing), i.e. drawn on."""
    width, height, rows = png_pixels(png)
    dark = sum(1 for row in rows for (r, g, b) in row if r + g + b < 735)
    return dark / float(width * height), width, height


def sample_configuration(vocabulary, place):
    """geometry/place_sample.hpp, independently: a division of two points its middle the short way
    round a periodic axis, else the middle point of the polyline (a face's sample, a join's point)."""
    points, axes = place["points"], vocabulary["axes"]
    if place["kind"] in ("fsd", "external-division") and len(points) == 2:
        q = []
        for k in range(2):
            a, b = points[0][k], points[1][k]
            d = b - a
            if axes[k]["periodic"]:
                span = axes[k]["hi"] - axes[k]["lo"]
                d -= span * round(d / span)
            v = a + d / 2
            if axes[k]["periodic"]:
                v = axes[k]["lo"] + (v - axes[k]["lo"]) % span
            q.append(v)
        return q
    return points[len(points) // 2]


def Select(element):
    from selenium.webdriver.support.ui import Select as Chosen
    return Chosen(element)


def rotation_degrees(transform):
    m = re.fullmatch(r"rotate\(([-0-9.eE+]+) [-0-9.eE+]+ [-0-9.eE+]+\)", transform or "")
    check(m is not None, "a turning part's transform is a rotation, not %r" % transform)
    return float(m.group(1))


def check_envisionment(driver, data, wheel, pallets, described):
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    chain = data["envisionment"]["chains"][0]
    states = {s["id"]: s for s in chain["states"]}
    nexts, prevs = {}, {}
    for t in chain["transitions"]:
        nexts.setdefault(t["from"], []).append(t["to"])
        prevs.setdefault(t["to"], []).append(t["from"])
    check(len(states) > 150, "the escapement has more states than the graph shows at once")
    nodes = driver.find_elements(By.CSS_SELECTOR, "#graph g.state")
    check(0 < len(nodes) <= 150, "the graph shows %d states" % len(nodes))
    check("at most" in driver.find_element(By.ID, "graph-note").text, "the page says the graph is shown in parts")
    shown = [int(n.get_attribute("data-state")) for n in nodes]
    check(all(s in states for s in shown), "the graph shows states of the envisionment")
    drawing = driver.find_element(By.ID, "state-drawing")

    def rotation(part):
        return rotation_degrees(drawing.find_element(By.CSS_SELECTOR, 'g.part[data-part="%s"]' % part).get_attribute("transform"))

    def expect_state(sid, how):
        check(drawing.get_attribute("data-state") == str(sid), "%s: state %s shown, not %d" % (how, drawing.get_attribute("data-state"), sid))
        listed = lambda which: sorted(int(b.get_attribute("data-state")) for b in driver.find_elements(By.CSS_SELECTOR, "#state-%s button" % which))
        check(listed("next") == sorted(nexts.get(sid, [])), "%s: state %d lists next states %r" % (how, sid, listed("next")))
        check(listed("previous") == sorted(prevs.get(sid, [])), "%s: state %d lists previous states %r" % (how, sid, listed("previous")))
        place = states[sid]["places"][0]["place"]
        sample = data["pairs"][0]["samples"][place]["config"]
        check(abs(rotation(wheel) - sample[0]) < 1e-6 and abs(rotation(pallets) - sample[1]) < 1e-6,
              "%s: state %d draws the parts at place %d's sample" % (how, sid, place))
        arrows = sorted((a.get_attribute("data-part"), a.get_attribute("data-motion"))
                        for a in drawing.find_elements(By.CSS_SELECTOR, "g.motions g.motion"))
        moving = sorted((part, m[1]) for part, m in states[sid]["motions"].items() if m != "(0)")
        check(arrows == moving, "%s: state %d's motion arrows %r, its motions %r" % (how, sid, arrows, moving))
        check(len(driver.find_elements(By.CSS_SELECTOR, "#state-cspace g.state-point circle")) == 1, "%s: the state's point" % how)

    # Selecting a state in the graph: one with next and previous states.
    target = next(s for s in shown if nexts.get(s) and prevs.get(s))
    node = driver.find_element(By.CSS_SELECTOR, '#graph g.state[data-state="%d"] circle' % target)
    driver.execute_script("arguments[0].scrollIntoView()", node)
    ActionChains(driver).move_to_element(node).click().perform()
    expect_state(target, "a click in the graph")
    check("selected" in driver.find_element(By.CSS_SELECTOR, '#graph g.state[data-state="%d"]' % target).get_attribute("class"), "highlighted")
    follow = driver.find_elements(By.CSS_SELECTOR, "#state-next button")[0]
    goto = int(follow.get_attribute("data-state"))
    follow.click()
    expect_state(goto, "a next state")

    # A history of four states along transitions, played.
    history = [target]
    while len(history) < 4:
        history.append(next((n for n in nexts.get(history[-1], []) if n not in history), None))
        check(history[-1] is not None, "a history of four states from %d" % target)
    field = driver.find_element(By.ID, "history-input")
    speed = driver.find_element(By.ID, "history-speed")
    speed.clear()
    speed.send_keys("150")

    def enter(text):
        field.clear()
        field.send_keys(text)

    enter(" ".join("#%d" % h for h in history))
    # Every state the drawing shows is recorded by the page itself (a MutationObserver), not by
    # polling from here: on a loaded machine a WebDriver round trip outlasts a 150 ms step.
    driver.execute_script(
        "const d = arguments[0]; window.qmShown = [+d.getAttribute('data-state')];"
        "new MutationObserver(() => { const s = +d.getAttribute('data-state');"
        " if (window.qmShown[window.qmShown.length - 1] !== s) window.qmShown.push(s); })"
        ".observe(d, {attributes: true, attributeFilter: ['data-state']});", drawing)
    driver.find_element(By.ID, "history-play").click()
    deadline = time.time() + 30
    while time.time() < deadline and driver.find_element(By.ID, "history-play").text != "Play":
        time.sleep(0.05)
    seen = driver.execute_script("return window.qmShown;")
    check(seen[-len(history):] == history, "playing %r showed %r" % (history, seen))
    check(driver.find_element(By.ID, "history-status").text.startswith("step 4 of 4"), "the history's last step")
    trail = driver.find_element(By.CSS_SELECTOR, "#state-cspace g.state-point polyline").get_attribute("points").split()
    check(len(trail) == 4, "the point's trail has %d points" % len(trail))
    played = driver.find_elements(By.CSS_SELECTOR, "#graph g.state.played")
    check(sorted(int(g.get_attribute("data-state")) for g in played) == sorted(history), "the graph shows the history's states")
    # `...`: the shortest path; a step with no transition is refused.
    enter("#%d ... #%d" % (history[0], history[3]))
    driver.find_element(By.ID, "history-forward").click()
    status = driver.find_element(By.ID, "history-status").text
    check(re.match(r"step 1 of [234]: #%d " % history[0], status) is not None, "'...' loads a shortest path: %r" % status)
    stranger = next(s for s in states if s not in nexts.get(history[0], []))
    enter("#%d #%d" % (history[0], stranger))
    driver.find_element(By.ID, "history-forward").click()
    check("no transition from #%d to #%d" % (history[0], stranger) in driver.find_element(By.ID, "history-status").text, "a bad step refused")
    # The described behaviour of `explore --path`, as `envision --path` answers it.
    want = [int(m) for m in re.findall(r"^  #(\d+) ", described, re.M)]
    check(len(want) >= 2 and data["paths"][0]["states"] == want, "the page's path %r, envision's %r" % (data["paths"][0]["states"], want))
    Select(driver.find_element(By.ID, "history-paths")).select_by_value("0")
    for k in range(2):
        driver.find_element(By.ID, "history-forward").click()
        expect_state(want[k], "step %d of the described behaviour" % (k + 1))


def check_transient(driver, qm_atms, source, work, cache):
    """cam_free.def's transient cycles and the escapement's possible rests are shown as such."""
    from selenium.webdriver.common.by import By
    for name, scene in (("cam_free", "scenarios/clock/cam_free.def"), ("escapement-full", "scenarios/clock/escapement.def")):
        out = os.path.join(work, name)
        run = subprocess.run([qm_atms, "explore", os.path.join(source, scene), "-o", out, "--cache", cache], capture_output=True, text=True)
        check(run.returncode == 0, "qm-atms explore %s failed: %s" % (scene, run.stderr))
        driver.get("file://" + os.path.abspath(os.path.join(out, "index.html")))
        chain = json.loads(driver.execute_script("return document.getElementById('qm-data').textContent"))["envisionment"]["chains"][0]
        views = [o.text for o in driver.find_elements(By.CSS_SELECTOR, "#graph-view option")]
        if name == "cam_free":
            check(chain["transient_cycles"], "cam_free has transient cycles")
            check(any(v.startswith("transient cycle 1 (") and "cannot repeat" in v for v in views), "views %r" % views)
            first = chain["transient_cycles"][0]
            sid, why = first["states"][0], "on transient cycle 1: it cannot repeat, %s moves %s throughout" % (first["object"], first["motion"][1:-1])
        else:
            check(chain["possible_rests"], "the escapement has possible rests")
            check(any(v.startswith("terminal states (") and "possible rests" in v for v in views), "views %r" % views)
            sid, why = chain["possible_rests"][0], "a possible rest: it may stay, or move on"
        field = driver.find_element(By.ID, "state-id")
        field.clear()
        field.send_keys(str(sid))
        driver.find_element(By.ID, "state-go").click()
        info = driver.find_element(By.ID, "state-info").text
        check(why in info, "state #%d of %s: %r" % (sid, scene, info))
        errors = [e for e in driver.get_log("browser") if e["level"] in ("SEVERE", "WARNING")]
        check(not errors, "console on %s: %r" % (scene, errors))


def main():
    qm_atms, source, work = sys.argv[1], sys.argv[2], sys.argv[3]
    chromium, chromedriver = shutil.which("chromium"), shutil.which("chromedriver")
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
        from selenium.webdriver.common.action_chains import ActionChains
        from selenium.webdriver.common.by import By
    except ImportError:
        webdriver = None
    missing = [name for name, found in (("chromium", chromium), ("chromedriver (chromium-driver)", chromedriver),
                                        ("Python's Selenium (python3-selenium)", webdriver)) if not found]
    if missing:
        print("SKIPPED: the explorer page's browser test needs %s, not installed here; "
              "cmake/install-deps.sh installs them (CI runs this test)" % ", ".join(missing))
        return SKIP

    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scene = os.path.join(source, SCENE)
    cache = os.path.join(work, "cache")
    run = subprocess.run([qm_atms, "explore", scene, "-o", os.path.join(work, "page"), "--cache", cache, "--path", DESCRIBED],
                         capture_output=True, text=True)
    check(run.returncode == 0, "qm-atms explore failed: " + run.stderr)
    envisioned = subprocess.run([qm_atms, "envision", scene, "--json", "--cache", cache], capture_output=True, text=True)
    check(envisioned.returncode == 0, "qm-atms envision failed: " + envisioned.stderr)
    described = subprocess.run([qm_atms, "envision", scene, "--path", DESCRIBED, "--cache", cache], capture_output=True, text=True)
    check(described.returncode == 0, "qm-atms envision --path failed: " + described.stderr)
    places = subprocess.run([qm_atms, "--places", scene, "--json", "--no-cache"], capture_output=True, text=True)
    check(places.returncode == 0, "qm-atms --places failed: " + places.stderr)
    vocabulary = json.loads(places.stdout)["pairs"][0]["vocabulary"]
    wheel, pallets = json.loads(places.stdout)["pairs"][0]["parts"]

    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for flag in FLAGS + ["--user-data-dir=" + tempfile.mkdtemp(dir=work)]:
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(chromedriver), options=options)
    try:
        driver.execute_cdp_cmd("Network.enable", {})
        driver.execute_cdp_cmd("Network.emulateNetworkConditions",
                               {"offline": True, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1})
        driver.set_window_size(1280, 900)
        url = "file://" + os.path.abspath(os.path.join(work, "page", "index.html"))
        driver.get(url)
        check(driver.execute_script("return document.readyState") == "complete", "the page did not load")
        check(driver.title == "qm-atms explorer: escapement", "title %r" % driver.title)
        resources = driver.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
        check(all(r.startswith("file://") for r in resources), "the page fetched %r" % resources)

        # The page's data is the --places vocabulary: same ids, kinds and points.
        data = json.loads(driver.execute_script("return document.getElementById('qm-data').textContent"))
        check(data["schema"] == "qm-explore/1", "the data blob's schema")
        check(data["envisionment"] == json.loads(envisioned.stdout), "the page's envisionment is not envision --json's")
        page_vocabulary = data["pairs"][0]["vocabulary"]
        check([(p["id"], p["kind"], p["points"]) for p in page_vocabulary["places"]] ==
              [(p["id"], p["kind"], p["points"]) for p in vocabulary["places"]], "the page's places differ from --places")

        def drawn():
            part = lambda name: driver.find_element(By.CSS_SELECTOR, '#drawing g.part[data-part="%s"]' % name).get_attribute("transform")
            return rotation_degrees(part(wheel)), rotation_degrees(part(pallets))

        def expect_place(place_id, how):
            q = sample_configuration(vocabulary, vocabulary["places"][place_id])
            w, p = drawn()
            for got, want, name in ((w, math.degrees(q[0]), wheel), (p, math.degrees(q[1]), pallets)):
                check(abs(got - want) < 1e-6, "%s: place %d draws %s at %.9f degrees, its sample is at %.9f" % (how, place_id, name, got, want))
            marks = len(driver.find_elements(By.CSS_SELECTOR, "#drawing g.contacts g.contact"))
            check(marks == data["pairs"][0]["samples"][place_id]["contacts"], "%s: place %d shows %d contact marks" % (how, place_id, marks))
            if vocabulary["places"][place_id]["kind"] == "cseg":
                check(marks >= 1, "%s: the parts touch at CSEG %d" % (how, place_id))
            check(("Place %d" % place_id) in driver.find_element(By.ID, "place-info").text, "%s: the info shows place %d" % (how, place_id))
            return marks

        check(drawn() == (0.0, 0.0), "the parts start as drawn")
        by_kind = {}
        for p in vocabulary["places"]:
            by_kind.setdefault(p["kind"], p["id"])
        select = Select(driver.find_element(By.ID, "place-select"))
        for kind in ("face", "join", "cseg", "fsd"):
            select.select_by_value(str(by_kind[kind]))
            expect_place(by_kind[kind], "the list")
        # Clicking a place's number in the configuration space.
        target = next(p["id"] for p in vocabulary["places"] if p["kind"] == "join" and p["id"] != by_kind["join"])
        number = driver.find_element(By.CSS_SELECTOR, '#cspace g.place-numbers text[data-place="%d"]' % target)
        ActionChains(driver).move_to_element(number).click().perform()
        expect_place(target, "a click")
        check("selected" in number.get_attribute("class"), "the clicked place is highlighted")
        # Pointing at another place shows it; leaving shows the selected one again.
        other = by_kind["face"]
        ActionChains(driver).move_to_element(driver.find_element(By.CSS_SELECTOR, '#cspace g.place-numbers text[data-place="%d"]' % other)).perform()
        expect_place(other, "hovering")
        ActionChains(driver).move_to_element(driver.find_element(By.ID, "title")).perform()
        expect_place(target, "leaving")
        # Following an adjacency: the first next place offered.
        go = driver.find_elements(By.CSS_SELECTOR, "#place-info button[data-goto]")
        check(len(go) > 0, "place %d offers next places" % target)
        goto = int(go[0].get_attribute("data-goto"))
        go[0].click()
        expect_place(goto, "an adjacency")

        check_envisionment(driver, data, wheel, pallets, described.stdout)
        Select(driver.find_element(By.ID, "graph-view")).select_by_value("0")  # the first group: more than a path

        # Screenshots at two window sizes: the pictures are there and drawn.
        for width, height in ((1280, 900), (700, 1100)):
            driver.set_window_size(width, height)
            for area in ("cspace", "drawing", "graph", "state-drawing"):
                element = driver.find_element(By.ID, area)
                driver.execute_script("arguments[0].scrollIntoView()", element)
                share, w, h = inked(element.screenshot_as_png)
                check(w > 200 and h > 150, "%s at %dx%d is %dx%d pixels" % (area, width, height, w, h))
                check(share > 0.03, "%s at %dx%d is blank (%.3f of it inked)" % (area, width, height, share))
                print("%s at %dx%d: %dx%d pixels, %.1f%% inked" % (area, width, height, w, h, 100 * share))

        errors = [e for e in driver.get_log("browser") if e["level"] in ("SEVERE", "WARNING")]
        check(not errors, "console: %r" % errors)
        check_transient(driver, qm_atms, source, work, cache)
    finally:
        driver.quit()
    print("PASS: the explorer page in %s" % chromium)
    return 0


if __name__ == "__main__":
    sys.exit(main())
