//! The pipeline end to end on small pictures, and the Nav2 inflation costs.

use envmap::{
    FORBIDDEN_COLOUR, Inflation, Mask, Picture, Pipeline, RECTANGLE_COLOUR, RISK_COLOUR,
    SAFE_COLOUR, binarize, distance_transform, render_zones,
};
use hyplan_core::{Point2, Workspace, Zone};

/// A white picture with an L-shaped dark obstacle.
fn l_shape() -> Picture {
    let mut pic = Picture::filled_rgb(30, 20, [250, 250, 250]);
    for y in 5..15 {
        pic.set_rgb(8, y, [30, 30, 30]);
    }
    for x in 8..18 {
        pic.set_rgb(x, 14, [30, 30, 30]);
    }
    pic
}

/// The L shape through the default pipeline with `rectangles` and `safety_radius`.
fn l_shape_through(rectangles: bool, safety_radius: f64) -> envmap::PipelineOutput {
    Pipeline {
        rectangles,
        safety_radius,
        ..Pipeline::default()
    }
    .run(&l_shape())
    .unwrap()
}

#[test]
fn l_shape_is_one_component_and_its_rectangle_fills_the_corner() {
    let exact = l_shape_through(false, 0.0);
    assert_eq!(exact.components.len(), 1);
    assert_eq!(exact.components[0].cells, 19);
    assert_eq!(exact.map.zone_counts(), [600 - 19, 0, 19]);
    let rect = l_shape_through(true, 0.0);
    assert_eq!(rect.map.zone_counts()[2], 10 * 10);
    // Pixel (12, 8), inside the L's corner, is free exactly but forbidden as a rectangle.
    assert_eq!(exact.map.cell_zone(12, 19 - 8), Zone::Free);
    assert_eq!(rect.map.cell_zone(12, 19 - 8), Zone::Forbidden);
}

#[test]
fn default_pipeline_follows_the_seed() {
    let p = Pipeline::default();
    assert_eq!(
        (p.threshold, p.invert, p.rectangles, p.safety_radius),
        (100, false, false, 20.0)
    );
    assert!(
        Pipeline {
            safety_radius: -1.0,
            ..p
        }
        .run(&l_shape())
        .is_err()
    );
    assert!(
        Pipeline {
            safety_radius: f64::NAN,
            ..p
        }
        .run(&l_shape())
        .is_err()
    );
}

#[test]
fn risk_band_blocks_only_when_avoiding_risk() {
    let out = l_shape_through(false, 3.0);
    // Row of pixel y = 3 (map row 16) passes 2 cells above the top of the L (pixel y = 5).
    let (a, b) = (Point2::new(0.5, 16.5), Point2::new(29.5, 16.5));
    assert_eq!(out.map.zone(Point2::new(8.5, 16.5)), Zone::Risk);
    assert!(out.map.segment_free(a, b));
    assert!(!out.map.clone().avoiding_risk().segment_free(a, b));
}

#[test]
fn invert_swaps_obstacles() {
    let pic = l_shape();
    let a = binarize(&pic, 100, false);
    let b = binarize(&pic, 100, true);
    assert!(a.cells().iter().zip(b.cells()).all(|(x, y)| x != y));
}

#[test]
fn render_uses_the_paper_colours() {
    let out = l_shape_through(true, 2.0);
    let pic = render_zones(&out.map, &out.rectangles);
    assert_eq!(pic.pixel(0, 0), &SAFE_COLOUR);
    assert_eq!(pic.pixel(8, 3), &RISK_COLOUR);
    assert_eq!(pic.pixel(12, 10), &FORBIDDEN_COLOUR); // inside the rectangle
    assert_eq!(pic.pixel(8, 5), &RECTANGLE_COLOUR); // its corner
}

#[test]
fn inflation_matches_nav2_compute_cost() {
    let mut mask = Mask::new(20, 1);
    mask.set(0, 0, true);
    let dist = distance_transform(&mask);
    let inf = Inflation {
        inscribed_radius: 0.16,
        inflation_radius: 0.55,
        cost_scaling_factor: 10.0,
    };
    let costs = inf.costs(&dist, 0.05).unwrap();
    assert_eq!(costs[0], 254);
    assert_eq!(&costs[1..4], &[253, 253, 253]); // 0.05, 0.10, 0.15 m <= 0.16 m
    // 0.20 m: 252 * exp(-10 * 0.04) = 168.9 -> 168 (Nav2 truncates).
    assert_eq!(costs[4], 168);
    for (k, &c) in costs.iter().enumerate() {
        assert_eq!(c, inf.cost(k as f64 * 0.05), "cell {k}");
    }
    assert!(costs[4..11].windows(2).all(|w| w[0] > w[1]));
    assert!(costs[10] > 0);
    assert_eq!(costs[12], 0); // 0.60 m > inflation_radius
    assert!(
        Inflation {
            inflation_radius: 0.1,
            ..inf
        }
        .costs(&dist, 0.05)
        .is_err()
    );
    assert!(inf.costs(&dist, 0.0).is_err());
}
