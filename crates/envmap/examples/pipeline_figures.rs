//! Draws the pictures of `docs/envmap.md`: each stage of the seed-000 pipeline on the
//! synthetic room of [`envmap::demo_room`].
//!
//! ```text
//! cargo run -p envmap --release --example pipeline_figures -- docs/figures
//! ```
//!
//! Writes `envmap_input.png`, `envmap_binary.png`, `envmap_rectangles.png`,
//! `envmap_zones.png` and `envmap_zones_exact.png`, and prints the counts.

use std::path::PathBuf;

use envmap::{Pipeline, RECTANGLE_COLOUR, demo_room, render_mask, render_zones, write_picture};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "docs/figures".into()),
    );
    std::fs::create_dir_all(&dir)?;
    // 640 x 480 pixels, safety radius 20 px (seed 000, section 4.1).
    let room = demo_room(640, 480);
    write_picture(&room, &dir.join("envmap_input.png"))?;

    let seed = Pipeline {
        rectangles: true,
        ..Pipeline::default()
    };
    let out = seed.run(&room)?;
    write_picture(&render_mask(&out.mask), &dir.join("envmap_binary.png"))?;

    // Rectangles: the binary picture with each component's bounding rectangle in blue.
    let mut rects = render_mask(&out.mask);
    let mut rgb = envmap::Picture::filled_rgb(rects.width(), rects.height(), [255; 3]);
    for y in 0..rects.height() {
        for x in 0..rects.width() {
            let v = rects.pixel(x, y)[0];
            rgb.set_rgb(x, y, [v, v, v]);
        }
    }
    rects = rgb;
    let h = rects.height();
    for r in &out.rectangles {
        for x in r.i_min..=r.i_max {
            rects.set_rgb(x, h - 1 - r.j_max, RECTANGLE_COLOUR);
            rects.set_rgb(x, h - 1 - r.j_min, RECTANGLE_COLOUR);
        }
        for j in r.j_min..=r.j_max {
            rects.set_rgb(r.i_min, h - 1 - j, RECTANGLE_COLOUR);
            rects.set_rgb(r.i_max, h - 1 - j, RECTANGLE_COLOUR);
        }
    }
    write_picture(&rects, &dir.join("envmap_rectangles.png"))?;
    write_picture(
        &render_zones(&out.map, &out.rectangles),
        &dir.join("envmap_zones.png"),
    )?;

    let exact = Pipeline::default().run(&room)?;
    write_picture(
        &render_zones(&exact.map, &[]),
        &dir.join("envmap_zones_exact.png"),
    )?;

    let [f, r, x] = out.map.zone_counts();
    let [fe, re, xe] = exact.map.zone_counts();
    println!("picture {} x {}", room.width(), room.height());
    println!("obstacle pixels {}", out.mask.count());
    println!("components {}", out.components.len());
    println!("rectangles: safe {f}, high-risk {r}, forbidden {x}");
    println!("exact:      safe {fe}, high-risk {re}, forbidden {xe}");
    Ok(())
}
