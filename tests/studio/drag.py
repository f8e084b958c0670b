"""The drag whose redraws are timed: a degree-20 Bézier curve, and a drag of one of its points
driven from inside the page. Shared by the end-to-end test (Playwright) and by
`bench/studio_drag.py` (a plain headless Chromium); needs only the standard library."""

import json
import math
import os
import statistics

# An async function of [index, moves, every]: drags point `index` along a wave with pointer
# events sent from inside the page every `every` ms (a 60 Hz mouse; moves that come while a
# frame is being drawn replace each other, so `interval` is the time between redraws), waits
# until the studio is idle, and returns the page's timings of the frames drawn.
DRAG_JS = """async ([index, moves, every]) => {
    window.studio.timings.length = 0;
    const host = document.querySelector('[data-view=plane] .host');
    const handle = host.querySelector(`[data-point-index="${index}"]`);
    const box = handle.getBoundingClientRect();
    const x = box.x + box.width / 2, y = box.y + box.height / 2;
    const fire = (type, k, target) => target.dispatchEvent(new PointerEvent(type, {
        clientX: x + k, clientY: y + 30 * Math.sin(k / 10), pointerId: 1,
        pointerType: 'mouse', isPrimary: true, bubbles: true,
        buttons: type === 'pointerup' ? 0 : 1,
    }));
    fire('pointerdown', 0, handle);
    for (let k = 1; k <= moves; k++) {
        await new Promise((r) => setTimeout(r, every));
        fire('pointermove', k, host);
    }
    fire('pointerup', moves, host);
    await window.studio.idle();
    // The last frame's `shown` is set after the next animation frame.
    await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 50)));
    return window.studio.timings.slice();
}"""


def degree20(path):
    """Writes a degree-20 Bézier curve (21 points along a wave, every other one raised) to
    `path` as a JSON model."""
    points = []
    for k in range(21):
        t = k / 20
        points.append({
            "x": 10 * t,
            "y": 3 * math.sin(2 * math.pi * t) + (2 if k % 2 else 0),
            "truth": round(0.5 + 0.4 * math.sin(3 * t), 3),
            "indeterminacy": round(0.3 * t, 3),
            "falsity": round(0.2 + 0.1 * math.cos(5 * t), 3),
        })
    path.write_text(json.dumps({"kind": "bezier", "name": "degree 20", "control_points": points}))


def summarise(timings, moves, every_ms):
    """The drag frames' timings (ms): median, 90th percentile and largest of each measure.

    latency: from the pointer event to the views drawn and laid out anew; shown: to the end of
    the first browser frame after that; work: from the request to drawn; interval: between
    frames; server: the server's time for the request; fetch: from the request to its answer;
    dom: from the answer to drawn (painting the canvases, updating the page)."""
    frames = [t for t in timings if t["preview"]]
    final = [t for t in timings if not t["preview"]]

    def stats(key):
        values = sorted(t[key] for t in frames if t[key] is not None)
        return {
            "median": round(statistics.median(values), 1),
            "p90": round(values[int(0.9 * (len(values) - 1))], 1),
            "max": round(values[-1], 1),
        }

    return {
        "moves": moves,
        "move_every_ms": every_ms,
        "frames": len(frames),
        "views_per_frame": frames[-1]["views"],
        "latency_ms": stats("latency"),
        "shown_ms": stats("shown"),
        "work_ms": stats("work"),
        "interval_ms": stats("interval"),
        "server_ms": stats("server"),
        "fetch_ms": stats("fetch"),
        "dom_ms": stats("dom"),
        "final_full_quality_work_ms": round(final[-1]["work"], 1) if final else None,
        "load_average": os.getloadavg(),
    }
