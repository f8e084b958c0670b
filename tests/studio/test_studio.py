"""End-to-end tests of `neutrospline studio` in headless Chromium: open a file, drag a control
point, refuse truth = 1.2 with the CLI's message, switch to a B-spline, undo, save, export the
SVG and PNG that `neutrospline plot` writes, refuse foreign origins; and time a drag of a
degree-20 curve. Screenshots of every step go to the output folder."""

import json
import math
import os
import shutil
import socket
import subprocess
import urllib.error
import urllib.request
from pathlib import Path

from drag import DRAG_JS, degree20, summarise

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "example1.json"


def open_page(page, studio):
    page.goto(studio.url)
    page.wait_for_function("window.studio && window.studio.renders() > 0")
    idle(page)


def idle(page):
    page.evaluate("window.studio.idle()")


def model(page):
    return page.evaluate("window.studio.model()")


def shot(page, out_dir, name):
    page.screenshot(path=str(out_dir / f"{name}.png"), full_page=True)


def drag_handle(page, index, dx, dy, steps=10):
    handle = page.locator(f'[data-point-index="{index}"]')
    box = handle.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, steps + 1):
        page.mouse.move(x + dx * k / steps, y + dy * k / steps)
    page.mouse.up()
    idle(page)


def request(studio, path, headers=None, body=None):
    req = urllib.request.Request(
        f"http://127.0.0.1:{studio.port}{path}", data=body, headers=headers or {}
    )
    try:
        with urllib.request.urlopen(req, timeout=10) as response:
            return response.status, response.read()
    except urllib.error.HTTPError as e:
        return e.code, e.read()


def test_edit_save_and_export(start_studio, page, binary, out_dir, tmp_path):
    file = tmp_path / "example1.json"
    shutil.copy(EXAMPLE, file)
    studio = start_studio(file)
    open_page(page, studio)
    shot(page, out_dir, "01-open")
    assert page.locator("[data-point-index]").count() == 4
    assert model(page)["control_points"][1] == {
        "name": "C1", "x": 3, "y": 6, "truth": 0.8, "indeterminacy": 0.1, "falsity": 0.1
    }

    # Drag C1 right by 80 and down by 60 screen pixels.
    curve_before = page.locator("#views [data-view=plane] polyline.curve").get_attribute("points")
    table_before = page.locator("#table-host tbody tr").nth(5).inner_text()
    sx, sy, _, _ = page.evaluate("window.studio.frame()")
    svg_box = page.locator("#views [data-view=plane] .figure svg").bounding_box()
    per_pixel = 1600 / svg_box["width"]  # figure pixels per screen pixel
    drag_handle(page, 1, 80, 60)
    moved = model(page)["control_points"][1]
    assert math.isclose(moved["x"], 3 + 80 * per_pixel / sx, abs_tol=0.02), moved
    assert math.isclose(moved["y"], 6 + 60 * per_pixel / sy, abs_tol=0.02), moved
    assert moved["x"] > 3.5 and moved["y"] < 5.5
    assert page.locator("#views [data-view=plane] polyline.curve").get_attribute("points") != curve_before
    assert page.locator("#table-host tbody tr").nth(5).inner_text() != table_before
    assert page.locator("#point-fields input[name=x]").input_value() == str(moved["x"])
    assert "moved point 1" in page.locator("[role=status]").inner_text()
    shot(page, out_dir, "02-dragged")

    # Truth 1.2 is refused with the reader's message, which `neutrospline check` prints too.
    page.fill("input[name=truth]", "1.2")
    page.press("input[name=truth]", "Enter")
    idle(page)
    message = "control_points[1]: truth = 1.2 is outside [0, 1] (every degree must be in [0, 1])"
    assert page.locator("[role=alert]").inner_text() == message
    assert page.locator('[data-error-for="truth"]').inner_text() == message
    assert model(page)["control_points"][1]["truth"] == 0.8
    bad = json.loads(EXAMPLE.read_text())
    bad["control_points"][1]["truth"] = 1.2
    (tmp_path / "bad.json").write_text(json.dumps(bad, indent=2))
    check = subprocess.run([binary, "check", tmp_path / "bad.json"], capture_output=True, text=True)
    assert check.returncode == 1
    assert check.stderr.strip().endswith(message), check.stderr
    shot(page, out_dir, "03-truth-refused")

    # B-spline: degree 3, clamped uniform knots written out.
    page.select_option("#model-kind", "bspline")
    idle(page)
    m = model(page)
    assert (m["kind"], m["degree"], m["knots"]) == ("bspline", 3, [0, 0, 0, 0, 1, 1, 1, 1])
    assert m["control_points"][1]["x"] == moved["x"]
    shot(page, out_dir, "04-bspline")

    # Undo (Ctrl+Z) goes back to the dragged Bézier curve; redo and undo again.
    page.locator("h1").click()
    page.keyboard.press("Control+z")
    idle(page)
    assert model(page)["kind"] == "bezier"
    page.keyboard.press("Control+Shift+z")
    idle(page)
    assert model(page)["kind"] == "bspline"
    page.keyboard.press("Control+z")
    idle(page)
    m = model(page)
    assert m["kind"] == "bezier" and m["control_points"][1] == moved
    shot(page, out_dir, "05-undone")

    # Save writes the started file: the original model with C1 moved, as the JSON writer writes it.
    page.click("#save")
    page.wait_for_function("document.querySelector('[role=status]').textContent.startsWith('saved')")
    expected = json.loads(EXAMPLE.read_text())
    expected["degree"] = 3
    expected["control_points"][1]["x"] = moved["x"]
    expected["control_points"][1]["y"] = moved["y"]
    saved = json.loads(file.read_text())
    assert saved == expected
    assert saved == model(page)
    assert subprocess.run([binary, "check", file], capture_output=True).returncode == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.json", "example1.json"]

    # Export SVG and PNG: the bytes `neutrospline plot` writes for the same model and view.
    for view in ["plane", "all"]:
        page.select_option("#export-view", view)
        for fmt in ["svg", "png"]:
            with page.expect_download() as info:
                page.click(f"#export-{fmt}")
            exported = out_dir / f"exported-{view}.{fmt}"
            info.value.save_as(exported)
            reference = tmp_path / f"plot-{view}.{fmt}"
            subprocess.run(
                [binary, "plot", file, "--view", view, "-o", reference], check=True
            )
            assert exported.read_bytes() == reference.read_bytes(), f"{view} {fmt}"
    shot(page, out_dir, "06-saved-exported")


def test_foreign_requests_are_refused(start_studio, page, out_dir):
    studio = start_studio()
    open_page(page, studio)
    assert model(page)["name"] == "Example 1"
    own = f"http://127.0.0.1:{studio.port}"
    body = json.dumps({"model": json.dumps(model(page)), "views": ["plane"]}).encode()
    json_type = {"Content-Type": "application/json"}
    assert request(studio, "/api/render", {"Origin": own, **json_type}, body)[0] == 200
    status, answer = request(studio, "/api/render", {"Origin": "http://evil.example", **json_type}, body)
    assert status == 403
    assert json.loads(answer)["error"]["message"] == "refused: Origin `http://evil.example` is not this studio"
    status, _ = request(studio, "/", {"Host": f"rebound.example:{studio.port}"})
    assert status == 403
    # Without a file there is nothing to save to.
    status, answer = request(studio, "/api/save", {"Origin": own, **json_type}, body)
    assert status == 409
    # A body over 16 MiB is refused from its Content-Length, before it is sent.
    with socket.create_connection(("127.0.0.1", studio.port), timeout=10) as s:
        s.sendall(
            f"POST /api/open HTTP/1.1\r\nHost: 127.0.0.1:{studio.port}\r\n"
            f"Content-Type: application/json\r\nContent-Length: {16 * 1024 * 1024 + 1}\r\n\r\n".encode()
        )
        answer = b""
        while chunk := s.recv(4096):
            answer += chunk
        answer = answer.decode()
    assert answer.startswith("HTTP/1.1 413 "), answer
    assert "larger than the limit of 16777216 bytes" in answer
    # A page on another origin cannot read the studio's answers either (no CORS headers).
    other = page.context.new_page()
    other.goto("about:blank")
    outcome = other.evaluate(
        """async (url) => {
            try { const r = await fetch(url + 'api/state'); return 'read ' + r.status; }
            catch (e) { return 'blocked'; }
        }""",
        studio.url,
    )
    assert outcome == "blocked"
    # The page still works after all that.
    page.fill("input[name=falsity]", "2")
    page.press("input[name=falsity]", "Enter")
    idle(page)
    assert "falsity = 2 is outside [0, 1]" in page.locator("[role=alert]").inner_text()
    shot(page, out_dir, "07-example-refusals")


def canvas_shown(page, view):
    return page.evaluate(
        """(view) => {
            const host = document.querySelector(`[data-view=${view}] .host`);
            return !host.querySelector('canvas.preview').hidden && host.querySelector('.figure').hidden;
        }""",
        view,
    )


def test_drag_frames_are_painted_on_canvases(start_studio, page, out_dir, tmp_path):
    """While a point is held and moved, every view shows a canvas painted from the server's
    display list (the figure's SVG hidden under it); when it is let go, the settled SVG
    figures are back and the model has the point where it was dropped."""
    file = tmp_path / "example1.json"
    shutil.copy(EXAMPLE, file)
    studio = start_studio(file)
    open_page(page, studio)
    views = ["plane", "controls", "truth", "indeterminacy", "falsity", "all"]
    assert not any(canvas_shown(page, v) for v in views)
    handle = page.locator('[data-point-index="2"]')
    box = handle.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 6):
        page.mouse.move(x + 8 * k, y - 6 * k)
    idle(page)
    assert all(canvas_shown(page, v) for v in views)
    # Each canvas is painted: white paper with ink on it, at the canvas's own pixel size.
    for view in views:
        ink = page.evaluate(
            """(view) => {
                const c = document.querySelector(`[data-view=${view}] canvas.preview`);
                const host = c.parentElement;
                const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
                let dark = 0;
                for (let i = 0; i < d.length; i += 4) if (d[i] + d[i + 1] + d[i + 2] < 300) dark++;
                return {dark: dark / (c.width * c.height), w: c.width, h: c.height,
                        cw: host.clientWidth, ch: host.clientHeight};
            }""",
            view,
        )
        assert (ink["w"], ink["h"]) == (ink["cw"], ink["ch"]), (view, ink)
        assert 0.002 < ink["dark"] < 0.3, (view, ink)
    # The handles follow the point during the drag.
    frame = page.evaluate("window.studio.frame()")
    held = model(page)["control_points"][2]
    pixel = page.evaluate(
        "[...document.querySelectorAll('[data-point-index]')].map(c => [+c.getAttribute('cx'), +c.getAttribute('cy')])[2]"
    )
    assert math.isclose(pixel[0], frame[2] + frame[0] * held["x"], abs_tol=0.01)
    assert math.isclose(pixel[1], frame[3] + frame[1] * held["y"], abs_tol=0.01)
    shot(page, out_dir, "09-dragging-canvases")
    page.mouse.up()
    idle(page)
    assert not any(canvas_shown(page, v) for v in views)
    assert page.locator("[data-view=plane] .figure svg").count() == 1
    dropped = model(page)["control_points"][2]
    assert dropped["x"] > 6 and dropped["y"] > 2, dropped
    assert "moved point 2" in page.locator("[role=status]").inner_text()


def test_canvas_frames_match_the_svg_figures(start_studio, page, out_dir):
    """A display list painted on a canvas and the SVG figure of the same drawing, rasterised by
    the browser at the same size, agree pixel for pixel up to anti-aliasing: every view of a
    2-D curve, a 3-D curve and a surface (meshes, clips, gradients, dashes, halos)."""
    studio = start_studio()
    open_page(page, studio)
    worst = {}
    for name in ["example1.toml", "helix3d.toml", "nurbs-surface.json"]:
        text = (ROOT / "examples" / name).read_text()
        compared = page.evaluate(
            """async ([name, text]) => {
                const post = (path, body) => fetch(path, {method: 'POST',
                    headers: {'Content-Type': 'application/json'}, body: JSON.stringify(body)})
                    .then((r) => r.json());
                const model = (await post('/api/open', {name, text})).model;
                const views = ['plane', 'controls', 'truth', 'indeterminacy', 'falsity', 'all', 'score'];
                const ask = (encoding) => post('/api/render', {model: JSON.stringify(model), views,
                    encoding, figure: {azimuth: 30, elevation: 20}, at: ''});
                const [svgs, lists] = [await ask('svg'), await ask('display-list')];
                const W = 800, H = 600, out = {};
                const pixels = (canvas) => canvas.getContext('2d').getImageData(0, 0, W, H).data;
                for (const view of views) {
                    const a = document.createElement('canvas');
                    a.width = W; a.height = H;
                    const img = new Image();
                    img.src = URL.createObjectURL(new Blob([svgs.figures[view]], {type: 'image/svg+xml'}));
                    await img.decode();
                    a.getContext('2d').drawImage(img, 0, 0, W, H);
                    const b = document.createElement('canvas');
                    b.width = W; b.height = H;
                    window.studio.paintDisplayList(b, lists.drawings[view]);
                    const [p, q] = [pixels(a), pixels(b)];
                    let far = 0, sum = 0;
                    for (let i = 0; i < p.length; i += 4) {
                        const d = Math.max(Math.abs(p[i] - q[i]), Math.abs(p[i + 1] - q[i + 1]), Math.abs(p[i + 2] - q[i + 2]));
                        sum += d;
                        if (d > 64) far++;
                    }
                    out[view] = {far: far / (W * H), mean: sum / (W * H), ops: lists.drawings[view].ops.length};
                }
                return out;
            }""",
            [name, text],
        )
        for view, c in compared.items():
            assert c["ops"] > 20, (name, view, c)
            # Measured: no pixel apart by more than 64 levels, a mean difference under 0.2.
            assert c["far"] < 0.002 and c["mean"] < 1.0, (name, view, c)
            worst[view] = max(worst.get(view, 0), c["mean"])
    print("canvas vs SVG, worst mean difference per view:", json.dumps(worst))


def test_drag_degree_20_redraws_quickly(start_studio, page, out_dir, tmp_path):
    """Drags a point of a degree-20 curve with six views side by side, then with one large:
    every frame redraws every view shown. The timings are printed and saved; the speed itself
    is measured by bench/studio_drag.py in a plain headless Chromium (Playwright's network
    instrumentation costs the page time on every request), and STUDIO_DRAG_BUDGET_MS makes
    this test fail above a median latency."""
    file = tmp_path / "degree20.json"
    degree20(file)
    studio = start_studio(file)
    open_page(page, studio)
    assert page.locator("[data-point-index]").count() == 21
    summaries = {}
    for layout in ["grid", "large"]:
        if layout == "large":
            page.select_option("#layout", "large")
            page.select_option("#large-view", "plane")
            idle(page)
        summaries[layout] = drag_and_time(page, 10)
        shot(page, out_dir, f"08-degree20-dragged-{layout}")
    (out_dir / "drag-degree20.json").write_text(json.dumps(summaries, indent=1))
    for layout, summary in summaries.items():
        print(f"drag, degree 20, layout {layout}:", json.dumps(summary["summary"]))
        assert summary["summary"]["frames"] >= 5
        previews = [t for t in summary["frames"] if t["preview"]]
        assert {t["views"] for t in previews} == {6 if layout == "grid" else 1}, layout
        assert not summary["frames"][-1]["preview"], "the drag ends on the settled SVG figures"
    budget = os.environ.get("STUDIO_DRAG_BUDGET_MS")
    if budget:
        median = summaries["grid"]["summary"]["latency_ms"]["median"]
        assert median <= float(budget), summaries["grid"]["summary"]


def drag_and_time(page, index, moves=120, every_ms=16):
    """Drags point `index` (drag.DRAG_JS) and summarises the timings of the frames drawn."""
    timings = page.evaluate(DRAG_JS, [index, moves, every_ms])
    return {"summary": summarise(timings, moves, every_ms), "frames": timings}


def test_points_rules_files_data_and_camera(start_studio, page, binary, out_dir, tmp_path):
    file = tmp_path / "example1.json"
    shutil.copy(EXAMPLE, file)
    studio = start_studio(file)
    open_page(page, studio)

    # Add after the last point, insert after the selected one, delete.
    page.click("#add-point")
    idle(page)
    m = model(page)
    assert (len(m["control_points"]), m["degree"]) == (5, 4)
    assert (m["control_points"][4]["x"], m["control_points"][4]["y"]) == (12, 8)
    page.select_option("#point-index", "1")
    page.click("#insert-point")
    idle(page)
    m = model(page)
    assert len(m["control_points"]) == 6
    assert (m["control_points"][2]["x"], m["control_points"][2]["y"]) == (4.5, 4)
    assert page.locator("[data-point-index]").count() == 6
    page.click("#delete-point")
    idle(page)
    assert len(model(page)["control_points"]) == 5

    # Arrow keys move the selected point.
    page.locator('[data-point-index="0"]').click()
    page.locator("h1").click()
    x0 = model(page)["control_points"][0]["x"]
    page.keyboard.press("ArrowRight")
    idle(page)
    assert model(page)["control_points"][0]["x"] > x0

    # Membership rules: intuitionistic drops the indeterminacy; fuzzy refuses nothing here.
    page.select_option("#model-membership", "intuitionistic")
    idle(page)
    m = model(page)
    assert m["membership"] == "intuitionistic"
    assert "indeterminacy" not in m["control_points"][1]
    assert page.locator("input[name=indeterminacy]").is_disabled()
    page.fill("input[name=falsity]", "0.9")
    page.press("input[name=falsity]", "Enter")
    idle(page)
    assert "intuitionistic rule: truth + falsity <= 1" in page.locator("[role=alert]").inner_text()
    shot(page, out_dir, "09-intuitionistic-refused")
    page.select_option("#model-membership", "neutrosophic")
    idle(page)
    assert model(page)["control_points"][1]["indeterminacy"] == 0.1
    # The families beyond the original three: Pythagorean drops the indeterminacy and refuses
    # truth^2 + falsity^2 > 1 with its rule; q-rung gets q = 3.
    page.select_option("#model-membership", "pythagorean")
    idle(page)
    m = model(page)
    assert m["membership"] == "pythagorean"
    assert "indeterminacy" not in m["control_points"][1]
    assert page.locator("input[name=indeterminacy]").is_disabled()
    # The views the family cannot draw: unticked, disabled, the reason as the title (no
    # command-line flag in it); the panel is not shown. The derived view draws the hesitation.
    box = page.locator('#view-toggles input[value="indeterminacy"]')
    assert box.is_disabled() and not box.is_checked()
    label = page.locator("#view-toggles label", has=page.locator('input[value="indeterminacy"]'))
    reason = label.get_attribute("title")
    assert reason == (
        "the view `indeterminacy` does not draw pythagorean models: pythagorean degrees are "
        "truth and falsity (no indeterminacy); draw the view `truth` or `falsity`"
    ), reason
    assert page.locator('figure.panel[data-view="indeterminacy"]').is_hidden()
    assert not page.locator('#view-toggles input[value="derived"]').is_disabled()
    assert page.locator(".view-error").count() == 0 or all(
        "--view" not in e for e in page.locator(".view-error").all_inner_texts()
    )
    header = page.locator("#table-host thead").inner_text().split()
    assert header[-3:] == ["truth", "falsity", "hesitation"], header
    page.fill("input[name=truth]", "0.9")
    page.press("input[name=truth]", "Enter")
    idle(page)
    page.fill("input[name=falsity]", "0.7")
    page.press("input[name=falsity]", "Enter")
    idle(page)
    assert "exceeds 1 (pythagorean rule)" in page.locator("[role=alert]").inner_text()
    shot(page, out_dir, "09b-pythagorean-refused")
    page.select_option("#model-membership", "q-rung")
    idle(page)
    assert model(page)["membership"] == "q-rung" and model(page)["q"] == 3
    page.select_option("#model-membership", "neutrosophic")
    idle(page)
    assert model(page)["membership"] == "neutrosophic" and "q" not in model(page)
    # Ticked again when the family draws it; a neutrosophic model derives no degrees.
    assert page.locator('#view-toggles input[value="indeterminacy"]').is_checked()
    assert page.locator('#view-toggles input[value="derived"]').is_disabled()

    # Open a file through the picker; a broken knot list is refused next to its field.
    page.set_input_files("#open-file", str(ROOT / "examples" / "bspline.toml"))
    page.wait_for_function("window.studio.model().kind === 'bspline'")
    idle(page)
    assert page.locator("[role=status]").inner_text() == "opened bspline.toml"
    page.fill("#model-knots", "0, 0, 0, 0, 0.7, 0.5, 0.8, 1, 1, 1, 1")
    page.press("#model-knots", "Enter")
    idle(page)
    message = "knots: knot 5 = 0.5 is less than knot 4 = 0.7 (knots must be non-decreasing)"
    assert page.locator("[role=alert]").inner_text() == message
    assert page.locator('[data-error-for="knots"]').inner_text() == message
    assert model(page)["knots"] == [0, 0, 0, 0, 0.2, 0.5, 0.7, 1, 1, 1, 1]
    shot(page, out_dir, "10-knots-refused")

    # Data over the curve, then a fit with `fit`'s options.
    page.set_input_files("#data-file", str(ROOT / "examples" / "data" / "survey.csv"))
    page.wait_for_function("document.querySelector('[data-view=data] svg') !== null")
    idle(page)
    assert page.locator("[data-view=data] .residual").count() == 80
    page.click("#data-section summary")
    page.select_option("#fit-target", "control-points")
    page.fill("#fit-value", "12")
    with page.expect_request("**/api/fit") as fit_request:
        page.click("#fit")
    # The options under `neutrospline fit`'s flag names.
    sent = fit_request.value.post_data_json["options"]
    assert sent["control-points"] == 12 and "controlPoints" not in sent, sent
    page.wait_for_function("window.studio.model().control_points.length === 12")
    idle(page)
    assert page.locator("[role=status]").inner_text() == "fitted 12 control points to survey.csv"
    assert "control points 12 (degree 3)" in page.locator("#fit-report").inner_text()
    shot(page, out_dir, "11-fitted")

    # Save as TOML: a download that the command reads back to the same model.
    with page.expect_download() as info:
        page.click("#save-toml")
    assert info.value.suggested_filename == "example1.toml"
    downloaded = tmp_path / "fitted.toml"
    info.value.save_as(downloaded)
    assert downloaded.read_text().startswith('kind = "bspline"')
    with page.expect_download() as info:
        page.click("#save-json")
    assert info.value.suggested_filename == "example1.json"
    info.value.save_as(tmp_path / "fitted.json")
    assert json.loads((tmp_path / "fitted.json").read_text()) == model(page)
    evals = [
        subprocess.run([binary, "eval", f, "--samples", "7"], capture_output=True, text=True, check=True).stdout
        for f in [downloaded, tmp_path / "fitted.json"]
    ]
    assert evals[0] == evals[1]

    # Turning a 3-D view by dragging it.
    before = page.evaluate("window.studio.camera()")
    box = page.locator("[data-view=truth] .host").bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    page.mouse.down()
    page.mouse.move(box["x"] + box["width"] / 2 + 60, box["y"] + box["height"] / 2 + 20, steps=6)
    page.mouse.up()
    idle(page)
    after = page.evaluate("window.studio.camera()")
    assert after["azimuth"] != before["azimuth"] and after["elevation"] > before["elevation"]
    shot(page, out_dir, "12-turned")

    # 3-D data fitted as a surface, with `fit --surface`'s options (issue 25).
    page.set_input_files("#data-file", str(ROOT / "examples" / "data" / "hill_grid.csv"))
    idle(page)
    page.check("#fit-surface")
    page.fill("#fit-grid", "12x10")
    page.select_option("#fit-target", "control-points")
    page.fill("#fit-value", "8,6")
    with page.expect_request("**/api/fit") as fit_request:
        page.click("#fit")
    body = fit_request.value.post_data_json
    assert body["surface"] is True and body["options"]["grid"] == "12x10", body
    assert body["options"]["control-points"] == [8, 6], body
    page.wait_for_function("window.studio.model().kind === 'bspline-surface'")
    idle(page)
    assert page.locator("[role=status]").inner_text() == "fitted 8 x 6 control points to hill_grid.csv"
    assert "control points 8 x 6 (degrees 3, 3)" in page.locator("#fit-report").inner_text()
    page.wait_for_function("document.querySelectorAll('[data-view=data] .residual').length === 120")
    shot(page, out_dir, "13-surface-fitted")


def drop_file(page, selector, name, text):
    transfer = page.evaluate_handle(
        """([name, text]) => {
            const dt = new DataTransfer();
            dt.items.add(new File([text], name));
            return dt;
        }""",
        [name, text],
    )
    page.dispatch_event(selector, "drop", {"dataTransfer": transfer})


def test_drop_broken_file_3d_curve_and_surface(start_studio, page, binary, out_dir, tmp_path):
    studio = start_studio()
    open_page(page, studio)

    # A broken file dropped on the page: the reader's message, as `check` prints it.
    broken = (ROOT / "examples" / "bspline.toml").read_text().replace("degree = 3", "degree = -3")
    (tmp_path / "broken.toml").write_text(broken)
    drop_file(page, "#views", "broken.toml", broken)
    page.wait_for_function("document.querySelector('[role=alert]').textContent !== ''")
    message = page.locator("[role=alert]").inner_text()
    assert message == "broken.toml:9: degree: expected a non-negative integer, found -3"
    check = subprocess.run([binary, "check", tmp_path / "broken.toml"], capture_output=True, text=True)
    assert check.stderr == f"error: {tmp_path / 'broken.toml'}:9: degree: expected a non-negative integer, found -3\n"
    assert model(page)["name"] == "Example 1"
    shot(page, out_dir, "13-broken-file-dropped")

    # A 3-D curve dropped: handles in the plane view select points; z is edited in its field.
    drop_file(page, "#views", "helix3d.toml", (ROOT / "examples" / "helix3d.toml").read_text())
    page.wait_for_function("window.studio.model().name === 'helix quarter turn'")
    idle(page)
    assert page.locator("[data-point-index]").count() == 4
    page.locator('[data-point-index="2"]').click()
    assert page.locator("#point-index").input_value() == "2"
    page.fill("input[name=z]", "0.6")
    page.press("input[name=z]", "Enter")
    idle(page)
    assert model(page)["control_points"][2]["z"] == 0.6
    # A space curve's point is dragged in the plane of the screen: the least move whose
    # picture is the pointer's move (the map comes from the server).
    drag_map = page.evaluate("window.studio.dragMap()")
    assert drag_map is not None and len(drag_map) == 3
    before = model(page)["control_points"][1]
    per_pixel = 1600 / page.locator("#views [data-view=plane] .figure svg").bounding_box()["width"]
    drag_handle(page, 1, 40, -30)
    after = model(page)["control_points"][1]
    dx, dy = 40 * per_pixel, -30 * per_pixel
    for i, axis in enumerate("xyz"):
        expected = before[axis] + drag_map[i][0] * dx + drag_map[i][1] * dy
        assert math.isclose(after[axis], expected, abs_tol=0.01), (axis, before, after, expected)
    assert math.dist([before[a] for a in "xyz"], [after[a] for a in "xyz"]) > 0.1
    assert (after["truth"], after["indeterminacy"], after["falsity"]) == (
        before["truth"], before["indeterminacy"], before["falsity"])
    assert "moved point 1 to (" in page.locator("[role=status]").inner_text()
    # The fields show the dropped point, even the one edited before the drag.
    assert float(page.locator("#point-fields input[name=z]").input_value()) == after["z"]
    shot(page, out_dir, "14-helix-3d")

    # A surface: every view draws; degrees of a control point are edited; no handles to drag.
    drop_file(page, "#views", "surface.toml", (ROOT / "examples" / "surface.toml").read_text())
    page.wait_for_function("window.studio.model().kind === 'bezier-surface'")
    idle(page)
    for view in ["plane", "controls", "truth", "indeterminacy", "falsity", "all"]:
        assert page.locator(f"[data-view={view}] .figure svg").count() == 1, view
    page.select_option("#point-index", "5")
    page.fill("input[name=truth]", "0.25")
    page.press("input[name=truth]", "Enter")
    idle(page)
    assert model(page)["control_points"][5]["truth"] == 0.25
    assert page.locator("#add-point").is_disabled()
    shot(page, out_dir, "15-surface")


def degree_sliders(page):
    return page.locator("#degree-fields input[type=range]").evaluate_all(
        "sliders => sliders.map(s => [s.dataset.slider, s.min, s.max, s.disabled])"
    )


def test_wide_families_interval_type2_and_bipolar(start_studio, page, out_dir, tmp_path):
    """The interval-valued and bipolar families: one slider per channel, as the server
    describes the family; the rule's refusal next to the field; the table of the channels and
    derived degrees; switching families converts the degrees by channel name. (The figures of
    these families are the plot crate's: the test asks nothing of them.)"""
    file = tmp_path / "interval-type2.toml"
    shutil.copy(ROOT / "examples" / "families" / "interval-type2.toml", file)
    studio = start_studio(file)
    open_page(page, studio)
    assert page.locator("#model-membership").input_value() == "interval-type2"
    assert page.locator("#model-membership option").count() == 13
    assert degree_sliders(page) == [
        ["truth_lower", "0", "1", False], ["truth_upper", "0", "1", False]
    ]
    assert page.locator("input[name=indeterminacy]").count() == 0
    assert page.locator("#rule-note").inner_text() == (
        "interval-type2: truth_lower, truth_upper each in [0, 1]; truth_lower <= truth_upper; "
        "derived: type_reduced, footprint"
    )
    header = page.locator("#table-host thead").inner_text().split()
    assert header == ["t", "x", "y", "truth_lower", "truth_upper", "type_reduced", "footprint"]
    first = page.locator("#table-host tbody tr").nth(0).inner_text().split()
    assert first == ["0", "0", "0", "0.2", "0.5", "0.35", "0.3"], first
    shot(page, out_dir, "16-interval-type2")

    # Point 1 (truth_lower 0.5, truth_upper 0.8): the truth_lower slider dragged to its right
    # end (1) is refused with the rule, next to the field.
    page.select_option("#point-index", "1")
    assert page.locator("input[name=truth_lower]").input_value() == "0.5"
    assert page.locator("input[name=truth_upper]").input_value() == "0.8"
    slider = page.locator("input[data-slider=truth_lower]")
    box = slider.bounding_box()
    y = box["y"] + box["height"] / 2
    page.mouse.move(box["x"] + 0.5 * box["width"], y)
    page.mouse.down()
    for k in range(1, 11):
        page.mouse.move(box["x"] + (0.5 + 0.06 * k) * box["width"], y)
    page.mouse.up()
    idle(page)
    message = ("control_points[1]: truth_lower = 1 exceeds truth_upper = 0.8 "
               "(interval-type2 rule: lower <= upper)")
    assert page.locator("[role=alert]").inner_text() == message
    assert page.locator('[data-error-for="truth_lower"]').inner_text() == message
    # The curve keeps the last value the rule allowed on the way (a preview frame).
    assert 0.5 <= model(page)["control_points"][1]["truth_lower"] <= 0.8
    shot(page, out_dir, "17-interval-type2-slider-refused")

    # Typed: truth_lower 0.6 with truth_upper 0.4 (point 3 has 0.4 and 0.6): the upper edited
    # first is refused next to it; the exact message of the rule.
    page.select_option("#point-index", "3")
    page.fill("input[name=truth_upper]", "0.3")
    page.press("input[name=truth_upper]", "Enter")
    idle(page)
    message = ("control_points[3]: truth_lower = 0.4 exceeds truth_upper = 0.3 "
               "(interval-type2 rule: lower <= upper)")
    assert page.locator("[role=alert]").inner_text() == message
    assert page.locator('[data-error-for="truth_upper"]').inner_text() == message
    assert page.locator('[data-error-for="truth_lower"]').inner_text() == ""
    page.fill("input[name=truth_upper]", "0.4")
    page.press("input[name=truth_upper]", "Enter")
    idle(page)
    assert model(page)["control_points"][3]["truth_upper"] == 0.4
    page.fill("input[name=truth_lower]", "0.6")
    page.press("input[name=truth_lower]", "Enter")
    idle(page)
    message = ("control_points[3]: truth_lower = 0.6 exceeds truth_upper = 0.4 "
               "(interval-type2 rule: lower <= upper)")
    assert page.locator("[role=alert]").inner_text() == message
    assert page.locator('[data-error-for="truth_lower"]').inner_text() == message
    assert page.locator("input[name=truth_lower]").evaluate("e => e.classList.contains('invalid')")
    assert model(page)["control_points"][3]["truth_lower"] == 0.4
    shot(page, out_dir, "18-interval-type2-typed-refused")

    # To neutrosophic: truth is the midpoint of the interval, indeterminacy and falsity 0.
    before = model(page)["control_points"]
    page.select_option("#model-membership", "neutrosophic")
    idle(page)
    m = model(page)
    assert m.get("membership", "neutrosophic") == "neutrosophic"
    for p, q in zip(m["control_points"], before):
        assert set(p) == {"x", "y", "truth", "indeterminacy", "falsity"}, p
        assert math.isclose(p["truth"], (q["truth_lower"] + q["truth_upper"]) / 2, abs_tol=1e-12)
        assert (p["indeterminacy"], p["falsity"]) == (0, 0)
    assert [s[0] for s in degree_sliders(page)] == ["truth", "indeterminacy", "falsity"]
    header = page.locator("#table-host thead").inner_text().split()
    assert header == ["t", "x", "y", "truth", "indeterminacy", "falsity"]
    # And back: a degenerate interval at each truth.
    page.select_option("#model-membership", "interval-type2")
    idle(page)
    m = model(page)
    assert m["membership"] == "interval-type2"
    for p, q in zip(m["control_points"], before):
        mid = (q["truth_lower"] + q["truth_upper"]) / 2
        assert set(p) == {"x", "y", "truth_lower", "truth_upper"}, p
        assert math.isclose(p["truth_lower"], mid, abs_tol=1e-12)
        assert p["truth_lower"] == p["truth_upper"]
    assert [s[0] for s in degree_sliders(page)] == ["truth_lower", "truth_upper"]
    # Point 3 (selected) had 0.4 and 0.4 since its upper bound was lowered.
    assert page.locator("#point-index").input_value() == "3"
    assert page.locator("input[name=truth_lower]").input_value() == "0.4"
    assert page.locator("input[name=truth_upper]").input_value() == "0.4"
    assert model(page)["control_points"][1]["truth_upper"] == model(page)["control_points"][1]["truth_lower"]

    # Bipolar: the positive degrees from the midpoint, the negative ones at 0 with sliders
    # on [-1, 0]; a negative degree above 0 is refused with its box.
    page.select_option("#model-membership", "bipolar-neutrosophic")
    idle(page)
    assert degree_sliders(page) == [
        ["truth", "0", "1", False], ["indeterminacy", "0", "1", False],
        ["falsity", "0", "1", False], ["negative_truth", "-1", "0", False],
        ["negative_indeterminacy", "-1", "0", False], ["negative_falsity", "-1", "0", False],
    ]
    p = model(page)["control_points"][3]
    assert (p["truth"], p["negative_truth"], p["negative_falsity"]) == (0.4, 0, 0)
    page.fill("input[name=negative_falsity]", "-0.25")
    page.press("input[name=negative_falsity]", "Enter")
    idle(page)
    assert model(page)["control_points"][3]["negative_falsity"] == -0.25
    assert page.locator("input[data-slider=negative_falsity]").input_value() == "-0.25"
    page.fill("input[name=negative_truth]", "0.2")
    page.press("input[name=negative_truth]", "Enter")
    idle(page)
    message = ("control_points[3]: negative_truth = 0.2 is outside [-1, 0] "
               "(bipolar-neutrosophic rule)")
    assert page.locator("[role=alert]").inner_text() == message
    assert page.locator('[data-error-for="negative_truth"]').inner_text() == message
    header = page.locator("#table-host thead").inner_text().split()
    assert header[3:] == ["truth", "indeterminacy", "falsity", "negative_truth",
                          "negative_indeterminacy", "negative_falsity"]
    shot(page, out_dir, "19-bipolar")

    # Interval-neutrosophic: six interval bounds from the bipolar positive degrees.
    page.select_option("#model-membership", "interval-neutrosophic")
    idle(page)
    p = model(page)["control_points"][3]
    assert (p["truth_lower"], p["truth_upper"], p["falsity_lower"]) == (0.4, 0.4, 0)
    assert [s[0] for s in degree_sliders(page)] == [
        "truth_lower", "truth_upper", "indeterminacy_lower", "indeterminacy_upper",
        "falsity_lower", "falsity_upper"]
    shot(page, out_dir, "20-interval-neutrosophic")
