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
    let (left, top, w, h) = plot_area(1, width, height);
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
    let (left, top, w, h) = plot_area(0, width, height);
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
