//! The renderer in a real headless Chromium (wasm-bindgen-test, `run_in_browser`): drawing a
//! known scene puts the expected colours at the expected pixels.
#![cfg(target_arch = "wasm32")]

use glam::{DQuat, DVec3};
use kli::{KliOptions, from_wxyz, kli};
use kli_demo::aircraft::aircraft;
use kli_demo::camera::{Camera, Viewport};
use kli_demo::object_view::draw_object;
use kli_demo::palette;
use kli_demo::pen::Pen;
use kli_demo::plots::{draw_plot_cursors, draw_plots, plot_area, time_axis_end};
use kli_demo::scene::Scene;
use kli_demo::sphere_view::{draw_sphere, draw_sphere_cursor};
use wasm_bindgen::JsCast;
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement};

wasm_bindgen_test_configure!(run_in_browser);

mod map_parts;

const WHITE: [u8; 3] = [255, 255, 255];

/// `#rrggbb` as bytes.
fn rgb(hex: &str) -> [u8; 3] {
    [1, 3, 5].map(|i| u8::from_str_radix(&hex[i..i + 2], 16).unwrap())
}

fn canvas(width: u32, height: u32) -> CanvasRenderingContext2d {
    let document = web_sys::window().unwrap().document().unwrap();
    let canvas: HtmlCanvasElement = document.create_element("canvas").unwrap().unchecked_into();
    canvas.set_width(width);
    canvas.set_height(height);
    document.body().unwrap().append_child(&canvas).unwrap();
    canvas.get_context("2d").unwrap().unwrap().unchecked_into()
}

fn pixel(ctx: &CanvasRenderingContext2d, (x, y): (f64, f64)) -> [u8; 3] {
    let data = ctx.get_image_data(x.round(), y.round(), 1.0, 1.0).unwrap().data();
    [data[0], data[1], data[2]]
}

fn paper_scene() -> Scene {
    Scene::new(
        kli(from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]), &KliOptions::default()).unwrap(),
    )
}

#[wasm_bindgen_test]
fn sphere_view_puts_markers_where_the_hopf_map_says() {
    let ctx = canvas(300, 300);
    let scene = paper_scene();
    let camera = Camera::orbit(135f64.to_radians(), 25f64.to_radians());
    let viewport = Viewport::fitting(0.0, 0.0, 300.0, 300.0, 1.22);
    let pen = Pen::begin(&ctx, 300.0, 300.0, 1.0, "#ffffff");
    draw_sphere(&pen, &viewport, &camera, &scene);
    draw_sphere_cursor(&Pen::over(&ctx, 1.0), &viewport, &camera, &scene, 0.85);
    let at = |v: DVec3| viewport.pixel(camera.project(v));
    assert_eq!(pixel(&ctx, (2.0, 2.0)), WHITE, "background");
    // The end h(r) = (0, 1, 0) (MATH.md) is a filled dark disc (#343a40).
    assert_eq!(pixel(&ctx, at(DVec3::Y)), [0x34, 0x3a, 0x40]);
    // The current KLI marker at t = 0.85: Table 1's q = (0.3083, 0.3083, 0.3083, 0.8455) through
    // eq. 5, computed here by hand: (a²+b²−c²−d², 2(ad+bc), 2(bd−ac)).
    let (a, d) = (0.3083_f64, 0.8455_f64);
    let h = DVec3::new(a * a + a * a - a * a - d * d, 2.0 * (a * d + a * a), 2.0 * (a * d - a * a))
        .normalize();
    assert_eq!(pixel(&ctx, at(h)), rgb(palette::KLI), "KLI marker at {h:?}");
    // The sphere's centre is shaded (grey-blue), not background.
    let [r, g, b] = pixel(&ctx, (150.0, 150.0));
    assert!(b > r && b < 255 && g < 255, "{r} {g} {b}");
}

#[wasm_bindgen_test]
fn object_view_shows_the_rotation() {
    // A point on the port (red, +y) wing. Turned by 180° about x, the starboard (green) wing
    // is there instead.
    let camera = Camera::orbit(0.0, 89f64.to_radians()); // from above: y to the left
    let viewport = Viewport::fitting(0.0, 0.0, 200.0, 200.0, 1.6);
    let probe = viewport.pixel(camera.project(DVec3::new(-0.1, 0.6, 0.0)));
    let mesh = aircraft();
    let ctx = canvas(200, 200);
    let pen = Pen::begin(&ctx, 200.0, 200.0, 1.0, "#ffffff");
    draw_object(&pen, &viewport, &camera, &mesh, DQuat::IDENTITY, false);
    let [r, g, _] = pixel(&ctx, probe);
    assert!(r > 150 && g < 90, "port wing should be red, got {r} {g}");
    let pen = Pen::begin(&ctx, 200.0, 200.0, 1.0, "#ffffff");
    draw_object(
        &pen,
        &viewport,
        &camera,
        &mesh,
        DQuat::from_rotation_x(std::f64::consts::PI),
        false,
    );
    let [r, g, _] = pixel(&ctx, probe);
    assert!(g > 100 && r < 90, "starboard wing should be green, got {r} {g}");
    // Far from the aircraft: background.
    assert_eq!(pixel(&ctx, (3.0, 3.0)), WHITE);
}

#[wasm_bindgen_test]
fn time_warp_plot_follows_the_closed_form() {
    let (width, height) = (900.0, 240.0);
    let ctx = canvas(width as u32, height as u32);
    let scene = paper_scene();
    let pen = Pen::begin(&ctx, width, height, 1.0, "#ffffff");
    draw_plots(&pen, width, height, &scene);
    let (left, top, w, h) = plot_area(1, width, height, 1.0);
    let x_max = time_axis_end(&scene);
    // s(t) = 1 − φ(t)/φ0 with tan(φ/2) = tan(π/6) e^−t: at t = 2, computed here.
    let phi0 = std::f64::consts::FRAC_PI_3;
    let t = 2.0_f64;
    let s = 1.0 - 2.0 * ((phi0 / 2.0).tan() * (-t).exp()).atan() / phi0;
    let x = left + t / x_max * w;
    let expected_y = top + (1.0 - s) * h;
    // Scan the column for the KLI colour (the 2 px curve; its edges are blended with white).
    let kli = rgb(palette::KLI);
    let found: Vec<f64> = (0..height as i32)
        .map(f64::from)
        .filter(|&y| {
            let p = pixel(&ctx, (x, y));
            (0..3).all(|c| (p[c] as i32 - kli[c] as i32).abs() < 40)
        })
        .collect();
    assert!(!found.is_empty(), "no KLI curve in column {x}");
    let mean = found.iter().sum::<f64>() / found.len() as f64;
    assert!((mean - expected_y).abs() < 2.0, "curve at y = {mean}, expected {expected_y}");
    // The time cursor at t = 6 on the distance plot: a dark dotted line at the computed x.
    draw_plot_cursors(&Pen::over(&ctx, 1.0), width, height, &scene, 6.0);
    let (left, top, w, h) = plot_area(0, width, height, 1.0);
    let x = left + 6.0 / x_max * w;
    // A 1 px antialiased line on a fractional x: look one pixel either side.
    let darkened =
        |y: i32| (-1..=1).any(|dx| pixel(&ctx, (x.floor() + f64::from(dx), f64::from(y)))[0] < 200);
    let rows = (top as i32 + 2..(top + h) as i32 - 2).filter(|&y| darkened(y)).count();
    assert!(rows as f64 > 0.3 * h, "cursor at x = {x}: {rows} darkened rows of {h}");
    // Elsewhere in the same rows, away from the curve, the plot stays white.
    let blank = (top as i32 + 2..(top + h) as i32 - 2)
        .filter(|&y| pixel(&ctx, (x + 25.0, f64::from(y)))[0] < 200)
        .count();
    assert!(blank < 10, "{blank} darkened rows 25 px to the right");
}

#[wasm_bindgen_test]
fn pixel_ratio_scales_the_drawing() {
    // At ratio 2 a 100×100 CSS-pixel drawing fills a 200×200 backing store.
    let ctx = canvas(200, 200);
    let scene = paper_scene();
    let camera = Camera::orbit(135f64.to_radians(), 25f64.to_radians());
    let viewport = Viewport::fitting(0.0, 0.0, 100.0, 100.0, 1.22);
    let pen = Pen::begin(&ctx, 100.0, 100.0, 2.0, "#ffffff");
    draw_sphere(&pen, &viewport, &camera, &scene);
    let end = viewport.pixel(camera.project(DVec3::Y));
    assert_eq!(pixel(&ctx, (2.0 * end.0, 2.0 * end.1)), [0x34, 0x3a, 0x40]);
}

#[wasm_bindgen_test]
fn svg_holds_real_vector_elements_and_escapes_text() {
    let pen = Pen::svg(200.0, 100.0, "#ffffff", "A <test> & \"figure\"");
    pen.polyline(&[(1.0, 2.0), (3.25, 4.5), (f64::NAN, 6.0)], "#c2410c", 2.0, &[6.0, 4.0]);
    pen.alpha(0.4);
    pen.disc((10.0, 20.0), 5.0, Some("#fff"), Some(("#000", 1.5)));
    pen.alpha(1.0);
    pen.dots(&[(1.0, 1.0), (5.0, 5.0)], 2.0, "#123456");
    pen.shaded_disc((50.0, 50.0), 40.0, "#fff", "#ccc");
    pen.text("t < 1 & s", (7.0, 8.0), "#343a40", 12.0, "center");
    pen.fill_polygon(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)], "rgb(1,2,3)", None);
    let svg = pen.finish();
    assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\""), "{svg}");
    assert!(svg.contains("<title>A &lt;test&gt; &amp; &quot;figure&quot;</title>"));
    assert!(svg.contains("points=\"1,2 3.25,4.5 0,6\""), "{svg}");
    assert!(svg.contains("stroke-dasharray=\"6 4\""));
    assert!(svg.contains("<circle cx=\"10\" cy=\"20\" r=\"5\" fill=\"#fff\" stroke=\"#000\" stroke-width=\"1.5\" opacity=\"0.4\"/>"), "{svg}");
    assert_eq!(svg.matches(" opacity=").count(), 1);
    assert!(svg.contains("M-1,1a2,2 0 1 0 4,0a2,2 0 1 0 -4,0M3,5"), "{svg}");
    assert!(svg.contains("fill=\"url(#shade0)\""));
    assert!(
        svg.contains(
            "text-anchor=\"middle\" dominant-baseline=\"central\">t &lt; 1 &amp; s</text>"
        )
    );
    assert!(svg.contains("<polygon points=\"0,0 1,0 0,1\" fill=\"rgb(1,2,3)\"/>"));
    assert!(svg.ends_with("</svg>\n"));
    // Estimated text widths grow with the text and the size, and are within 3% of what this
    // browser measures for the figures' labels (the first pictures are laid out so).
    let pen = Pen::svg(1.0, 1.0, "#fff", "");
    assert!(pen.text_width("abcd", 12.0) > pen.text_width("ab", 12.0));
    // DejaVu Sans's advances of a and b: 0.613 and 0.635 em.
    assert!((pen.text_width("ab", 10.0) - 12.48).abs() < 1e-12);
    let ctx = canvas(10, 10);
    let measured = Pen::over(&ctx, 1.0);
    for label in [
        "geodesic (Karcher)",
        "quaternion",
        "88.88°",
        "KLI  t = 0.00",
        "SLERP: u = t/T",
        "distance ‖r − q(t)‖ (log)",
    ] {
        let (estimate, width) = (pen.text_width(label, 11.0), measured.text_width(label, 11.0));
        assert!(
            (estimate / width - 1.0).abs() < 0.03,
            "{label}: estimated {estimate}, measured {width}"
        );
    }
}

#[wasm_bindgen_test]
fn the_svg_backend_draws_the_same_curve_as_the_canvas() {
    let (ctx, scene) = (canvas(300, 300), paper_scene());
    let camera = Camera::orbit(135f64.to_radians(), 25f64.to_radians());
    let viewport = Viewport::fitting(0.0, 0.0, 300.0, 300.0, 1.22);
    draw_sphere(&Pen::begin(&ctx, 300.0, 300.0, 1.0, "#ffffff"), &viewport, &camera, &scene);
    let svg = Pen::svg(300.0, 300.0, "#ffffff", "sphere");
    draw_sphere(&svg, &viewport, &camera, &scene);
    let svg = svg.finish();
    // The KLI curve's solid polylines: every 4th point is drawn on the canvas too (within a
    // pixel: antialiasing).
    let kli_stroke = format!("stroke=\"{}\"", palette::KLI);
    // Markers (discs) are drawn over the curve: points under them are left out.
    let centres: Vec<(f64, f64)> = svg
        .split("<circle cx=\"")
        .skip(1)
        .map(|c| {
            let x = c.split('"').next().unwrap().parse().unwrap();
            let y = c.split("cy=\"").nth(1).unwrap().split('"').next().unwrap().parse().unwrap();
            (x, y)
        })
        .collect();
    let mut checked = 0;
    for element in svg.split("<polyline ").skip(1).filter(|e| e.contains(&kli_stroke)) {
        if element.contains("stroke-dasharray") {
            continue; // the dashed part behind the sphere has gaps by design
        }
        let points = element.split("points=\"").nth(1).unwrap().split('"').next().unwrap();
        for xy in points.split(' ').step_by(3) {
            let (x, y) = xy.split_once(',').unwrap();
            let (x, y): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
            if centres.iter().any(|&(cx, cy)| (cx - x).hypot(cy - y) < 8.0) {
                continue;
            }
            let near = [(0.0, 0.0), (1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)]
                .iter()
                .any(|(dx, dy)| pixel(&ctx, (x + dx, y + dy)) != WHITE);
            assert!(near, "({x}, {y}) of the SVG curve is blank on the canvas");
            checked += 1;
        }
    }
    assert!(checked > 20, "{checked} points checked");
}

/// The text elements of an SVG document: their boxes (by the canvas's measure of the pen's
/// font, anchored as the SVG anchors them, the baseline central) and their text.
fn text_boxes(svg: &str, ctx: &CanvasRenderingContext2d) -> Vec<([f64; 4], String)> {
    let attribute = |element: &str, name: &str| -> String {
        let start = element.find(&format!(" {name}=\"")).map(|i| i + name.len() + 3);
        start.and_then(|s| element[s..].find('"').map(|e| element[s..s + e].to_owned())).unwrap()
    };
    let unescape = |t: &str| {
        t.replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", "\"").replace("&amp;", "&")
    };
    svg.split("<text ")
        .skip(1)
        .map(|rest| {
            let (element, after) = rest.split_once('>').unwrap();
            let element = &format!(" {element}");
            let text = unescape(after.split_once("</text>").unwrap().0);
            let number = |name: &str| attribute(element, name).parse::<f64>().unwrap();
            let (x, y, size) = (number("x"), number("y"), number("font-size"));
            ctx.set_font(&format!("{size}px system-ui, -apple-system, 'Segoe UI', sans-serif"));
            let width = ctx.measure_text(&text).unwrap().width();
            let left = match attribute(element, "text-anchor").as_str() {
                "middle" => x - width / 2.0,
                "end" => x - width,
                _ => x,
            };
            ([left, y - size / 2.0, left + width, y + size / 2.0], text)
        })
        .collect()
}

/// A label wider than twice its distance, its point due right of the centre: set straight out
/// it would cover the point, so it turns to a place clear of the point's mark; a short label
/// stays straight out; and what is placed is taken.
#[wasm_bindgen_test]
fn a_wide_label_clears_its_own_point() {
    use kli_demo::legend::{clear_place, outward, overlap, text_box};
    use kli_demo::pen::Pen;

    let pen = Pen::svg(300.0, 300.0, "#ffffff", "test");
    let (point, centre) = ((200.0, 150.0), (150.0, 150.0));
    let mut taken = Vec::new();
    let wide = "h(q): the nose";
    let mark = pen.disc(point, 7.0, Some("#c2410c"), Some(("#212529", 2.0)));
    assert_eq!(mark, 8.0);
    assert!(pen.text_width(wide, 12.0) > 2.0 * 18.0 + 2.0 * mark);
    let at = clear_place(&pen, wide, (point, centre), mark, 18.0, 12.0, &mut taken);
    let own = [point.0 - mark, point.1 - mark, point.0 + mark, point.1 + mark];
    assert!(!overlap(&text_box(&pen, wide, at, 12.0), &own), "{at:?}");
    assert!((at.0 - point.0).hypot(at.1 - point.1) - 18.0 < 1e-9, "{at:?}");
    assert_ne!(at, (218.0, 150.0));
    assert_eq!(taken, [text_box(&pen, wide, at, 12.0)]);
    let short = clear_place(&pen, "k1", ((100.0, 40.0), centre), mark, 18.0, 12.0, &mut Vec::new());
    assert_eq!(short, outward((100.0, 40.0), centre, 18.0));
}

/// A label is kept off its own point's mark as far as that mark reaches: the swarm's leader, a
/// disc of 8 pixels with a 2-pixel ring, reaches 9 pixels, past the 7 that every mark was once
/// given. Set so that its box would start 8 pixels out, the label turns for the leader's mark
/// and stays for a 7-pixel one.
#[wasm_bindgen_test]
fn a_label_clears_its_points_whole_mark() {
    use kli_demo::legend::{clear_place, outward, overlap, text_box};
    use kli_demo::pen::Pen;

    let pen = Pen::svg(300.0, 300.0, "#ffffff", "test");
    let (point, centre) = ((200.0, 150.0), (150.0, 150.0));
    let text = "pinned";
    let distance = 8.0 + 0.5 * pen.text_width(text, 12.0);
    let away = outward(point, centre, distance);
    let small = clear_place(&pen, text, (point, centre), 7.0, distance, 12.0, &mut Vec::new());
    assert_eq!(small, away);
    let leader = pen.disc(point, 8.0, Some("#c2410c"), Some(("#212529", 2.0)));
    assert_eq!(leader, 9.0);
    let at = clear_place(&pen, text, (point, centre), leader, distance, 12.0, &mut Vec::new());
    assert_ne!(at, away);
    let own = [point.0 - leader, point.1 - leader, point.0 + leader, point.1 + leader];
    assert!(!overlap(&text_box(&pen, text, at, 12.0), &own), "{at:?}");
}

/// A legend row (drawn over a plot's curves, inside its panel on a phone) sits on a white band,
/// drawn before its words, that holds every one of them: the lines under it do not run through.
#[wasm_bindgen_test]
fn a_legend_row_sits_on_a_white_band_that_holds_its_words() {
    use kli_demo::legend::{Entry, Mark, draw_legend_row};
    use kli_demo::pen::Pen;

    let pen = Pen::svg(300.0, 100.0, "#ffffff", "test");
    let entries = [
        Entry { mark: Mark::Line("#c2410c", 3.0, &[]), label: "KLI chain, smoothness 1" },
        Entry { mark: Mark::Line("#212529", 1.5, &[2.0, 3.0]), label: "piecewise SLERP" },
    ];
    draw_legend_row(&pen, (290.0, 50.0), &entries);
    let svg = pen.finish();
    let band = svg.find("<polygon").expect("a band");
    assert!(band < svg.find("<text").unwrap(), "the band is drawn before the words");
    let element = &svg[band..];
    assert!(element.split('>').next().unwrap().contains("fill=\"#ffffff\""), "{element}");
    let points = element.split("points=\"").nth(1).unwrap().split('"').next().unwrap();
    let xy: Vec<(f64, f64)> = points
        .split(' ')
        .map(|p| p.split_once(',').unwrap())
        .map(|(x, y)| (x.parse().unwrap(), y.parse().unwrap()))
        .collect();
    let (left, right) = xy.iter().fold((f64::MAX, f64::MIN), |(l, r), p| (l.min(p.0), r.max(p.0)));
    let (top, bottom) = xy.iter().fold((f64::MAX, f64::MIN), |(t, b), p| (t.min(p.1), b.max(p.1)));
    let boxes = text_boxes(&svg, &canvas(300, 100));
    assert_eq!(boxes.len(), 2);
    for ([l, t, r, b], text) in boxes {
        assert!(l >= left && r <= right && t >= top && b <= bottom, "{text}: {l} {t} {r} {b}");
    }
}

/// Every view of every page class, at the pages' sizes on a wide screen and at 390 px wide:
/// no two labels of a figure overlap (by more than half a pixel each way).
#[wasm_bindgen_test]
fn no_two_labels_of_a_figure_overlap() {
    use js_sys::{Float64Array, Object, Reflect};
    use kli_demo::{AverageDemo, KeyframesDemo, KliDemo, LearnDemo, SwarmDemo, SyncDemo};
    use wasm_bindgen::JsValue;

    let frame = |width: f64, height: f64, t: f64| {
        let frame = Object::new();
        for (key, value) in [("width", width), ("height", height), ("t", t)] {
            Reflect::set(&frame, &key.into(), &value.into()).unwrap();
        }
        JsValue::from(frame)
    };
    let quaternion = |q: [f64; 4]| JsValue::from(Float64Array::from(&q[..]));
    let paper = KliDemo::new(
        quaternion([0.0, 0.0, 0.0, 1.0]).unchecked_ref(),
        quaternion([0.5; 4]).unchecked_ref(),
        None,
    )
    .unwrap();
    let tumble = [
        1.0, 0.0, 0.0, 0.0, 0.8, 0.6, 0.0, 0.0, 0.5, 0.5, 0.5, 0.5, 0.0, 0.6, 0.8, 0.0, -0.3, 0.1,
        0.7, 0.64, 0.2, -0.6, 0.3, 0.72,
    ];
    let keyframes = KeyframesDemo::new(&tumble, &[], 1.0).unwrap();
    let options = Object::new();
    Reflect::set(&options, &"count".into(), &500.0.into()).unwrap();
    let swarm = SwarmDemo::new(Some(JsValue::from(options).unchecked_into())).unwrap();
    let average = AverageDemo::new(None).unwrap();
    let shares: Vec<f64> = (0..11).map(|i| i as f64 / 20.0).collect();
    let errors: Vec<f64> =
        shares.iter().flat_map(|&share| AverageDemo::sweep_point(None, share).unwrap()).collect();
    // 40 nodes: this debug build solves slowly, and the labels do not depend on the count.
    let small = || {
        let options = Object::new();
        Reflect::set(&options, &"count".into(), &40.0.into()).unwrap();
        Some(JsValue::from(options).unchecked_into())
    };
    let mut sync = SyncDemo::new(small()).unwrap();
    // On the way to agreement, where the plots have a history and the edges every colour.
    while !sync.seek(1.0) {}
    let sync_shares = [0.0, 0.1, 0.2, 0.3, 0.4];
    let sync_errors: Vec<f64> = sync_shares
        .iter()
        .flat_map(|&share| {
            ["spectral", "chordal", "robust"]
                .map(|method| SyncDemo::sweep_error(small(), share, method).unwrap())
        })
        .collect();
    // The tour at its start, and with every control moved: the lock, a double turn about the
    // diagonal rolled, SLERP near its end, ε = 1e-8 with a coarse δ, RK4 at a fine step, the
    // keyframe chain at smoothness 0 (its jumps written at the keys).
    let learn = LearnDemo::new(None).unwrap();
    let moved = Object::new();
    for (key, value) in [
        ("pitch", JsValue::from(90.0)),
        ("axis", JsValue::from("diagonal")),
        ("angle", JsValue::from(360.0)),
        ("roll", JsValue::from(120.0)),
        ("s", JsValue::from(0.9)),
        ("digits", JsValue::from(8.0)),
        ("delta", JsValue::from(0.3)),
        ("integrator", JsValue::from("rk4")),
        ("step", JsValue::from(0.1)),
        ("smoothness", JsValue::from(0.0)),
    ] {
        Reflect::set(&moved, &key.into(), &value).unwrap();
    }
    let learn_moved = LearnDemo::new(Some(JsValue::from(moved).unchecked_into())).unwrap();
    // (view, wide screen size, phone size) of each class, as the pages lay them out.
    let sphere = [(560.0, 420.0), (358.0, 268.0)];
    let svgs: Vec<(String, String)> = [
        ("object", [(560.0, 420.0), (358.0, 420.0)]),
        ("hopf", sphere),
        ("filmstrip", [(1100.0, 220.0), (358.0, 120.0)]),
        ("plots", [(1100.0, 360.0), (358.0, 420.0)]),
    ]
    .iter()
    .flat_map(|(view, sizes)| {
        sizes.map(|(w, h)| (format!("kli {view} {w}×{h}"), paper.to_svg(view, &frame(w, h, 3.0))))
    })
    .chain(
        [
            ("objects", [(1100.0, 300.0), (358.0, 600.0)]),
            ("hopf", sphere),
            ("plots", [(1100.0, 360.0), (358.0, 420.0)]),
        ]
        .iter()
        .flat_map(|(view, sizes)| {
            sizes.map(|(w, h)| {
                (format!("keyframes {view} {w}×{h}"), keyframes.to_svg(view, &frame(w, h, 1.5)))
            })
        }),
    )
    .chain(
        [
            ("hopf", sphere),
            ("objects", [(560.0, 300.0), (358.0, 300.0)]),
            ("plots", [(560.0, 300.0), (358.0, 300.0)]),
        ]
        .iter()
        .flat_map(|(view, sizes)| {
            sizes.map(|(w, h)| {
                (format!("swarm {view} {w}×{h}"), swarm.to_svg(view, &frame(w, h, 0.0)))
            })
        }),
    )
    .chain(
        [
            ("hopf", sphere),
            ("objects", [(560.0, 360.0), (358.0, 360.0)]),
            ("means", [(1100.0, 190.0), (358.0, 190.0)]),
        ]
        .iter()
        .flat_map(|(view, sizes)| {
            sizes.map(|(w, h)| {
                (format!("average {view} {w}×{h}"), average.to_svg(view, &frame(w, h, 2.0)))
            })
        }),
    )
    .chain([(1100.0, 240.0), (358.0, 240.0)].map(|(w, h)| {
        let svg = AverageDemo::sweep_svg(&frame(w, h, 0.0), &shares, &errors, 0.2);
        (format!("average sweep {w}×{h}"), Ok(svg))
    }))
    .chain(
        [
            ("graph", [(676.0, 420.0), (340.0, 380.0)]),
            ("hopf", [(444.0, 420.0), (340.0, 420.0)]),
            ("objects", [(444.0, 280.0), (340.0, 280.0)]),
            ("plots", [(1150.0, 240.0), (340.0, 480.0)]),
            ("results", [(676.0, 280.0), (340.0, 560.0)]),
        ]
        .iter()
        .flat_map(|(view, sizes)| {
            sizes.map(|(w, h)| {
                (format!("sync {view} {w}×{h}"), sync.to_svg(view, &frame(w, h, 0.0)))
            })
        }),
    )
    .chain([(1150.0, 240.0), (340.0, 240.0)].map(|(w, h)| {
        let svg = SyncDemo::sweep_svg(&frame(w, h, 0.0), &sync_shares, &sync_errors, 0.1);
        (format!("sync sweep {w}×{h}"), Ok(svg))
    }))
    .chain(
        // As www/first-pictures.json measures the tour's canvases; early, midway and at the end.
        [
            ("euler", [(770.0, 300.0), (340.0, 300.0)]),
            ("turn", [(770.0, 300.0), (340.0, 300.0)]),
            ("cover", [(770.0, 320.0), (340.0, 380.0)]),
            ("slerp", [(770.0, 300.0), (340.0, 300.0)]),
            ("hopf", [(370.0, 320.0), (340.0, 320.0)]),
            ("rolled", [(370.0, 300.0), (340.0, 300.0)]),
            ("phases", [(770.0, 300.0), (340.0, 400.0)]),
            ("lohe", [(770.0, 340.0), (340.0, 340.0)]),
            ("kli", [(770.0, 320.0), (340.0, 320.0)]),
            ("clock", [(770.0, 220.0), (340.0, 220.0)]),
            ("steps", [(770.0, 260.0), (340.0, 260.0)]),
            ("drift", [(770.0, 280.0), (340.0, 280.0)]),
            ("rates", [(770.0, 320.0), (340.0, 460.0)]),
        ]
        .iter()
        .flat_map(|(view, sizes)| {
            let (learn, learn_moved) = (&learn, &learn_moved);
            sizes.iter().flat_map(move |&(w, h)| {
                [(0.2, learn), (2.0, learn_moved), (12.0, learn)].map(|(t, run)| {
                    (format!("learn {view} {w}×{h} at {t}"), run.to_svg(view, &frame(w, h, t)))
                })
            })
        }),
    )
    .map(|(name, svg)| (name, svg.unwrap()))
    .collect();
    let ctx = canvas(1, 1);
    let mut overlaps = Vec::new();
    for (name, svg) in &svgs {
        let boxes = text_boxes(svg, &ctx);
        assert!(!boxes.is_empty(), "{name}: no labels");
        for (i, (a, text_a)) in boxes.iter().enumerate() {
            for (b, text_b) in &boxes[i + 1..] {
                let shared = |lo: usize, hi: usize| a[hi].min(b[hi]) - a[lo].max(b[lo]);
                if shared(0, 2) > 0.5 && shared(1, 3) > 0.5 {
                    overlaps.push(format!("{name}: \"{text_a}\" and \"{text_b}\""));
                }
            }
        }
    }
    assert!(overlaps.is_empty(), "labels overlap:\n{}", overlaps.join("\n"));
}

/// The averaging sphere names each of the four means beside a ring of its own colour, so that it
/// reads alone (a <kli-figure>, a slide, its SVG), away from the page's bars that share the
/// colours.
#[wasm_bindgen_test]
fn the_averaging_sphere_names_each_mean_in_its_own_colour() {
    use js_sys::{Object, Reflect};
    use kli_demo::AverageDemo;
    use wasm_bindgen::JsValue;

    let frame = Object::new();
    for (key, value) in [("width", 800.0), ("height", 600.0)] {
        Reflect::set(&frame, &key.into(), &value.into()).unwrap();
    }
    let svg = AverageDemo::new(None).unwrap().to_svg("hopf", &JsValue::from(frame)).unwrap();
    assert!(!svg.contains("bars"), "the legend points to the page's bars");
    let mut colours = Vec::new();
    for label in
        ["the chordal mean", "the quaternion mean", "the geodesic (Karcher) mean", "the median"]
    {
        let at =
            svg.find(&format!(">{label}<")).unwrap_or_else(|| panic!("no legend entry {label:?}"));
        // Its mark, drawn just before its text: a ring (a white disc with a coloured stroke).
        let mark = &svg[svg[..at].rfind("<circle").expect("a mark before the label")..at];
        let stroke =
            mark.split("stroke=\"").nth(1).and_then(|s| s.split('"').next()).expect("a ring");
        colours.push(stroke.to_string());
    }
    let mut distinct = colours.clone();
    distinct.sort();
    distinct.dedup();
    assert_eq!(distinct.len(), 4, "the four means' rings share colours: {colours:?}");
}
