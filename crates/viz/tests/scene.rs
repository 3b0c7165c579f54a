use std::path::Path;

use envmap::decode_picture;
use hyplan_core::Point2;
use viz::{GridImage, Mark, Scene, Stroke, apng_indexed, apng_scenes};

const WHITE: [u8; 4] = [255, 255, 255, 255];
const BLACK: [u8; 4] = [0, 0, 0, 255];
const GREY: [u8; 4] = [187, 187, 187, 255];

/// `width x height` cells of side `resolution` from the world's origin.
fn frame(width: usize, height: usize, resolution: f64) -> envmap::CellFrame {
    envmap::CellFrame::new(Point2::new(0.0, 0.0), resolution, width, height)
}

/// A 4 m x 2 m world at 10 px/m: a map layer with one black cell, a tree, a track, a
/// person, a frontier point and a moving robot.
fn tiny() -> Scene {
    let mut map = GridImage::filled(frame(4, 2, 1.0), vec![WHITE, BLACK]);
    map.set(3, 1, 1);
    let mut scene =
        Scene::new(Point2::new(0.0, 0.0), Point2::new(4.0, 2.0), 10.0).with_background(GREY);
    scene.push(Mark::Grid(map));
    scene.push(Mark::Segments {
        pairs: vec![(Point2::new(0.5, 0.5), Point2::new(1.5, 0.5))],
        stroke: Stroke::new([60, 120, 200, 110], 1.0),
    });
    scene.push(Mark::Polyline {
        points: vec![Point2::new(0.5, 0.5), Point2::new(2.5, 0.5)],
        stroke: Stroke::new([0, 170, 0, 255], 2.0).dashed(4.0, 2.0),
        title: Some("person 0".into()),
    });
    scene.push(Mark::disc(Point2::new(2.5, 1.5), 0.3, [238, 136, 0, 255]));
    scene.push(Mark::ring(
        Point2::new(1.5, 1.5),
        0.3,
        Stroke::new([238, 0, 0, 255], 2.0),
    ));
    scene.push(Mark::Moving {
        times: vec![0.0, 1.0],
        frames: vec![
            Mark::disc(Point2::new(0.5, 0.5), 0.2, [0, 170, 0, 204]),
            Mark::disc(Point2::new(1.5, 0.5), 0.2, [0, 170, 0, 204]),
        ],
    });
    scene
}

#[test]
fn svg_has_every_element() {
    let svg = tiny().to_svg().unwrap();
    assert!(svg.starts_with(r#"<svg xmlns="http://www.w3.org/2000/svg" width="40" height="20""#));
    assert_eq!(svg.matches("<rect").count(), 1, "the background");
    assert_eq!(svg.matches("<image").count(), 1, "the map layer");
    assert_eq!(svg.matches("<path").count(), 2, "tree and track");
    assert!(svg.contains("<title>person 0</title>"));
    assert!(svg.contains(r#"stroke-dasharray="4.00 2.00""#));
    assert_eq!(svg.matches("<circle").count(), 3, "person, ring, robot");
    assert_eq!(svg.matches("<animate ").count(), 2, "robot cx and cy");
    assert!(svg.contains(r#"values="5.00;15.00""#), "{svg}");
    assert!(svg.contains("#ee8800") && svg.contains(r#"fill-opacity="0.800""#));
}

#[test]
fn png_decodes_with_map_cells_and_marks() {
    let bytes = tiny().png_bytes().unwrap();
    let png = decode_picture(&bytes, Path::new("t.png")).unwrap();
    assert_eq!((png.width(), png.height()), (40, 20));
    // Cell (3, 1) is the top-right 10 px square: black; (3, 0) below it white.
    assert_eq!(&png.pixel(35, 5)[..3], &BLACK[..3]);
    assert_eq!(&png.pixel(35, 15)[..3], &WHITE[..3]);
    // The person's disc is orange at its centre (2.5, 1.5) -> (25, 5).
    assert_eq!(&png.pixel(25, 5)[..3], &[238, 136, 0]);
}

#[test]
fn frames_of_moving_marks() {
    let scene = tiny();
    let last = scene.at_frame(1);
    assert!(last.marks.iter().all(|m| !matches!(m, Mark::Moving { .. })));
    assert_eq!(
        last.marks.last(),
        Some(&Mark::disc(Point2::new(1.5, 0.5), 0.2, [0, 170, 0, 204]))
    );
    let apng = apng_scenes(&[scene.at_frame(0), last], 100).unwrap();
    let png = decode_picture(&apng, Path::new("a.png")).unwrap();
    assert_eq!((png.width(), png.height()), (40, 20));
    assert!(apng.windows(4).any(|w| w == b"acTL"), "animated");
}

#[test]
fn indexed_animation_keeps_the_palette_and_checks_sizes() {
    let a = GridImage::filled(frame(3, 2, 0.5), vec![WHITE, BLACK]);
    let mut b = a.clone();
    b.paint(Point2::new(1.4, 0.9), 1);
    assert_eq!(b.get(2, 1), 1);
    let bytes = apng_indexed([a.clone(), b], 100).unwrap();
    assert!(bytes.windows(4).any(|w| w == b"acTL"));
    assert!(bytes.windows(4).any(|w| w == b"PLTE"));
    let png = decode_picture(&bytes, Path::new("a.png")).unwrap();
    assert_eq!((png.width(), png.height()), (3, 2));
    let other = GridImage::filled(frame(2, 2, 0.5), vec![WHITE]);
    assert!(matches!(
        apng_indexed([a, other], 100),
        Err(viz::FigureError::FrameSize { index: 1, .. })
    ));
    assert!(matches!(
        apng_indexed(Vec::new(), 100),
        Err(viz::FigureError::NoFrames)
    ));
}

#[test]
fn grid_from_cells_checks_size_and_palette() {
    assert!(GridImage::from_cells(frame(2, 2, 1.0), vec![WHITE], vec![0; 3]).is_err());
    assert!(GridImage::from_cells(frame(2, 1, 1.0), vec![WHITE], vec![0, 1]).is_err());
    let g = GridImage::from_cells(frame(2, 1, 1.0), vec![WHITE, BLACK], vec![0, 1]).unwrap();
    assert_eq!(g.colour(1, 0), BLACK);
}
