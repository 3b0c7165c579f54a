use base64::Engine as _;
use envmap::{GridMap, decode_picture, render_zones};
use hyplan_core::{Goal, Point2, Query};
use std::path::Path;
use viz::{CURVE_COLOUR, Mark, PATH_COLOUR, PlanFigure, hex};

fn map() -> GridMap {
    GridMap::from_ascii(
        "
        ..........
        ..~~~~....
        ..~##~....
        ..~~~~....
        ..........
        ",
    )
    .unwrap()
}

fn query() -> Query {
    Query::new(
        Point2::new(0.5, 0.5),
        Goal::disc(Point2::new(9.5, 4.5), 0.4),
    )
}

/// The PNG's pixel at the centre of every cell is that cell's colour in
/// `envmap::render_zones`, where no mark is drawn.
#[test]
fn png_zone_layer_is_render_zones_scaled() {
    let map = map();
    let query = query();
    let figure = PlanFigure::new(&map, &query);
    let bytes = figure.png_bytes().unwrap();
    let png = decode_picture(&bytes, Path::new("t.png")).unwrap();
    let zones = render_zones(&map, &[]);
    let s = figure.scale() as usize;
    assert_eq!(s, 60, "10 cells wide -> 600 px");
    assert_eq!((png.width(), png.height()), (600, 300));
    let mut checked = 0;
    for y in 0..map.height() {
        for x in 0..map.width() {
            // Skip the cells under the start and goal markers.
            if (x, y) == (0, 4) || (x, y) == (9, 0) {
                continue;
            }
            let px = png.pixel(x * s + s / 2, y * s + s / 2);
            assert_eq!(&px[..3], zones.pixel(x, y), "cell ({x}, {y})");
            checked += 1;
        }
    }
    assert_eq!(checked, 48);
}

/// The SVG embeds the same zone layer as the PNG (decoded pixel for pixel) and draws
/// the raw path and the curve in their colours.
#[test]
fn svg_embeds_the_same_zone_layer_and_draws_path_and_curve() {
    let map = map();
    let query = query();
    let path = [query.start, Point2::new(9.5, 0.5), Point2::new(9.5, 4.5)];
    let curve = [query.start, Point2::new(5.0, 0.6), Point2::new(9.5, 4.5)];
    let svg = PlanFigure::new(&map, &query)
        .path(&path)
        .curve(&curve)
        .to_svg()
        .unwrap();
    let start = svg.find("data:image/png;base64,").unwrap() + "data:image/png;base64,".len();
    let end = start + svg[start..].find('"').unwrap();
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(&svg[start..end])
        .unwrap();
    let embedded = decode_picture(&bytes, Path::new("svg")).unwrap();
    let plain = PlanFigure::new(&map, &query).png_bytes().unwrap();
    let plain = decode_picture(&plain, Path::new("t.png")).unwrap();
    // The plain PNG has the markers on top; compare away from them.
    let (w, h) = (embedded.width(), embedded.height());
    assert_eq!((w, h), (plain.width(), plain.height()));
    for (x, y) in [(150, 150), (210, 120), (330, 90), (450, 200), (590, 290)] {
        assert_eq!(embedded.pixel(x, y), &plain.pixel(x, y)[..3], "({x}, {y})");
    }
    assert!(svg.contains(&hex(PATH_COLOUR)), "raw path");
    assert!(svg.contains(&hex(CURVE_COLOUR)), "curve");
    // Only the zone layer is a raster; nothing else draws cells.
    assert_eq!(svg.matches("<image").count(), 1);
    assert_eq!(svg.matches("<rect").count(), 0);
}

/// Marks are in world coordinates; the scene puts the start at cell (0, 0) of the map
/// (bottom-left) near the picture's bottom-left corner, y down.
#[test]
fn marks_land_on_pixels_y_down() {
    let map = map();
    let query = query();
    let path = [query.start, Point2::new(9.5, 4.5)];
    let figure = PlanFigure::new(&map, &query).path(&path);
    let marks = figure.marks();
    let Some(Mark::Polyline { points, .. }) = marks.first() else {
        panic!("first mark is the path: {marks:?}")
    };
    let scene = figure.scene();
    assert_eq!(scene.to_px(points[0]), [30.0, 270.0]);
    assert_eq!(scene.to_px(points[1]), [570.0, 30.0]);
}
