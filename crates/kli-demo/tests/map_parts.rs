//! A large pose graph's map drawn a part at a time (the synchronisation page draws w10000's a
//! task at a time): the parts in order draw what the whole does, each within its budget. In
//! Chromium, as the SVG pen writes its numbers with JavaScript's.
#![cfg(target_arch = "wasm32")]

use glam::DVec3;
use kli_demo::palette::BACKGROUND;
use kli_demo::pen::Pen;
use kli_demo::sync::map_view::{Look, MapPanel, PART_SEGMENTS, Parts, WHOLE_SEGMENTS, draw_map};
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};

wasm_bindgen_test_configure!(run_in_browser);

/// `n` poses on a spiral, each joined to the next (the trajectory) and to the one `n / 3` on
/// (a loop closure), the misfits running through every class.
fn spiral(n: usize) -> (Vec<[usize; 2]>, Vec<DVec3>, Vec<f64>) {
    let positions: Vec<DVec3> = (0..n)
        .map(|i| {
            let a = 0.01 * i as f64;
            DVec3::new((1.0 + a) * a.cos(), (1.0 + a) * a.sin(), 0.0)
        })
        .collect();
    let mut edges: Vec<[usize; 2]> = (0..n - 1).map(|i| [i, i + 1]).collect();
    edges.extend((0..n - n / 3).map(|i| [i, i + n / 3]));
    let misfits = (0..edges.len()).map(|k| (k % 11) as f64 * 0.5).collect();
    (edges, positions, misfits)
}

/// The SVG of `paint`'s drawing.
fn svg(mut paint: impl FnMut(&Pen)) -> String {
    let pen = Pen::svg(900.0, 500.0, BACKGROUND, "map");
    paint(&pen);
    pen.finish()
}

/// The segments in an SVG's paths: each is written `M x,y L x,y`.
fn segments(svg: &str) -> usize {
    svg.as_bytes()
        .windows(2)
        .filter(|w| w[0] == b'L' && (w[1].is_ascii_digit() || w[1] == b'-'))
        .count()
}

/// Draws the spiral's two panels (the optimum a little moved), in `parts`.
fn draw(pen: &Pen, n: usize, truth: bool, parts: &mut Parts) {
    let (edges, initial, misfits) = spiral(n);
    let optimum: Vec<DVec3> = initial.iter().map(|p| 0.9 * *p).collect();
    let panel = |positions| MapPanel {
        heading: "h".into(),
        line: "f".into(),
        positions,
        misfits: &misfits,
    };
    let panels = [panel(&initial[..]), panel(&optimum[..])];
    let truth = truth.then_some(&initial[..]);
    draw_map(pen, &edges, &panels, truth, &Look::Above, (900.0, 500.0), parts);
}

#[wasm_bindgen_test]
fn a_large_map_drawn_part_by_part_is_the_map_drawn_whole() {
    // 2 panels × (11,999 + 8,000) edges: 39,998 segments, over the truth's 12,000 points.
    let n = 12_000;
    let whole = svg(|pen| draw(pen, n, true, &mut Parts::new(None)));
    let mut counted = Parts::new(None);
    let _ = svg(|pen| draw(pen, n, true, &mut counted));
    let count = counted.count();
    assert!(count >= 3, "{count} parts");
    assert_eq!(segments(&whole), 2 * (n - 1 + n - n / 3), "the spiral's edges, in both panels");
    let pieces = svg(|pen| {
        for part in 0..count {
            let mut parts = Parts::new(Some(part));
            draw(pen, n, true, &mut parts);
            assert_eq!(parts.count(), count, "every part counts the same parts");
        }
    });
    assert_eq!(pieces, whole);
    // Each part draws something, and at most its budget of segments (the truth, a polyline of
    // 12,000 points, is a stroke longer than a part: it stands alone in the first).
    let empty = svg(|_| {});
    for part in 0..count {
        let alone = svg(|pen| draw(pen, n, true, &mut Parts::new(Some(part))));
        let drawn = segments(&alone);
        assert!(alone != empty && drawn <= PART_SEGMENTS, "part {part}: {drawn} segments");
    }
    // Parts are filled: each takes strokes (at most 2,000 segments) until the next would pass
    // its budget, so the spiral's 39,998 segments take at most 7 parts of over 6,000 after the
    // first (the truth's).
    assert!(count <= 1 + 39_998usize.div_ceil(PART_SEGMENTS - 2_000), "{count} parts");
    let past = svg(|pen| draw(pen, n, true, &mut Parts::new(Some(count))));
    assert_eq!(past, empty, "a part past the last draws nothing");
}

#[wasm_bindgen_test]
fn a_map_is_one_part_up_to_whole_segments_and_in_parts_beyond() {
    // 2 panels × (2,999 + 2,000) edges: 9,998 segments, more than a part's budget.
    let n = 3_000;
    assert!(2 * (n - 1 + n - n / 3) > PART_SEGMENTS && 2 * (n - 1 + n - n / 3) <= WHOLE_SEGMENTS);
    let mut parts = Parts::new(Some(0));
    let first = svg(|pen| draw(pen, n, false, &mut parts));
    assert_eq!(parts.count(), 1);
    assert_eq!(first, svg(|pen| draw(pen, n, false, &mut Parts::new(None))));
    // Just over: 2 panels × (7,999 + 5,334) edges, 26,666 segments, are drawn in parts.
    let n = 8_000;
    assert!(2 * (n - 1 + n - n / 3) > WHOLE_SEGMENTS);
    let mut parts = Parts::new(Some(0));
    let _ = svg(|pen| draw(pen, n, false, &mut parts));
    assert!(parts.count() > 1, "{} parts", parts.count());
}
