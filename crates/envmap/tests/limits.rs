//! ROS maps with a yaw (Nav2's reading) and the memory limit on every format.

use envmap::{DEFAULT_MAX_CELLS, InputFrame, LoadOptions, MapError, load_map};
use hyplan_core::{Point2, Workspace};

fn tmp(name: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("envmap_limits");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn close(a: Point2, b: Point2) -> bool {
    (a - b).norm() < 1e-12
}

/// A 4 x 2 map (resolution 0.5) with origin [1, 2, pi/2]: the grid's x axis points along
/// the map frame's +y. Its corners in the map frame, by hand: lower-left (1, 2),
/// lower-right (grid +2 m along x) (1, 4), upper-left (grid +1 m along y) (0, 2),
/// upper-right (0, 4).
#[test]
fn ros_map_with_a_yaw_is_rotated_about_its_origin() {
    // Top row first: the top-left pixel is black (occupied), the rest white (free).
    std::fs::write(
        tmp("yaw.pgm"),
        b"P2\n4 2\n255\n0 255 255 255\n255 255 255 255\n",
    )
    .unwrap();
    let yaml = tmp("yaw.yaml");
    std::fs::write(
        &yaml,
        "image: yaw.pgm\nresolution: 0.5\norigin: [1.0, 2.0, 1.5707963267948966]\n\
         negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n",
    )
    .unwrap();
    let loaded = load_map(&yaml, &LoadOptions::default()).unwrap();
    let yaw = std::f64::consts::FRAC_PI_2;
    assert_eq!(
        loaded.frame,
        InputFrame::MapFrame {
            origin: Point2::new(1.0, 2.0),
            yaw
        }
    );
    // The grid is axis-aligned in its own frame, pinned at the origin.
    let b = loaded.map.bounds();
    assert_eq!(
        (b.min, b.max),
        (Point2::new(1.0, 2.0), Point2::new(3.0, 3.0))
    );
    let f = loaded.frame;
    for (map_frame, grid) in [
        ((1.0, 2.0), Point2::new(1.0, 2.0)),
        ((1.0, 4.0), Point2::new(3.0, 2.0)),
        ((0.0, 2.0), Point2::new(1.0, 3.0)),
        ((0.0, 4.0), Point2::new(3.0, 3.0)),
    ] {
        let g = f.to_world(map_frame.0, map_frame.1);
        assert!(close(g, grid), "{map_frame:?} -> {g:?}, expected {grid:?}");
        let (x, y) = f.from_world(grid);
        assert!(close(
            Point2::new(x, y),
            Point2::new(map_frame.0, map_frame.1)
        ));
    }
    // The occupied pixel is grid cell (0, 1) = [1, 1.5] x [2.5, 3], which the yaw puts at
    // [0, 0.5] x [2, 2.5] in the map frame.
    assert!(!loaded.map.is_free(f.to_world(0.25, 2.25)));
    assert!(loaded.map.is_free(f.to_world(0.75, 2.25)));
    assert!(loaded.map.is_free(f.to_world(0.25, 2.75)));
    // Outside the rotated footprint (the unrotated one would contain it).
    assert!(!loaded.map.is_free(f.to_world(2.0, 2.5)));
}

fn too_large(path: &std::path::Path, max_cells: usize) -> MapError {
    let opts = LoadOptions {
        max_cells,
        ..LoadOptions::default()
    };
    load_map(path, &opts).unwrap_err()
}

fn assert_too_large(e: &MapError, w: usize, h: usize, limit: usize) {
    let MapError::TooLarge {
        width,
        height,
        limit: l,
        ..
    } = e
    else {
        panic!("expected TooLarge, got {e:?}");
    };
    assert_eq!((*width, *height, *l), (w, h, limit));
    let text = e.to_string();
    assert!(text.contains(&format!("{w} x {h}")), "{text}");
    assert!(text.contains(&format!("limit of {limit} cells")), "{text}");
}

/// Headers declaring 30,000 x 30,000 cells are refused from the header alone, before
/// any pixel or row is read (the files are a few bytes).
#[test]
fn maps_above_the_memory_limit_are_refused_from_their_header() {
    let n = 30_000;
    assert!(n * n > DEFAULT_MAX_CELLS);
    let pgm = tmp("huge.pgm");
    std::fs::write(&pgm, format!("P5\n{n} {n}\n255\n")).unwrap();
    assert_too_large(&too_large(&pgm, DEFAULT_MAX_CELLS), n, n, DEFAULT_MAX_CELLS);
    let ppm = tmp("huge.ppm");
    std::fs::write(&ppm, format!("P6\n{n} {n}\n255\n")).unwrap();
    assert_too_large(&too_large(&ppm, DEFAULT_MAX_CELLS), n, n, DEFAULT_MAX_CELLS);
    // A PNG of 30000 x 30000 grey pixels with no image data.
    let png = tmp("huge.png");
    let mut ihdr = Vec::new();
    ihdr.extend_from_slice(&(n as u32).to_be_bytes());
    ihdr.extend_from_slice(&(n as u32).to_be_bytes());
    ihdr.extend_from_slice(&[8, 0, 0, 0, 0]);
    let mut bytes = b"\x89PNG\r\n\x1a\n".to_vec();
    bytes.extend_from_slice(&13u32.to_be_bytes());
    let mut chunk = b"IHDR".to_vec();
    chunk.extend_from_slice(&ihdr);
    bytes.extend_from_slice(&chunk);
    bytes.extend_from_slice(&crc32(&chunk).to_be_bytes());
    // An IDAT with an empty zlib stream, then IEND: the header is all the reader needs.
    for (kind, data) in [
        (&b"IDAT"[..], &b"\x78\x9c\x03\x00\x00\x00\x00\x01"[..]),
        (b"IEND", b""),
    ] {
        bytes.extend_from_slice(&(data.len() as u32).to_be_bytes());
        let mut chunk = kind.to_vec();
        chunk.extend_from_slice(data);
        bytes.extend_from_slice(&chunk);
        bytes.extend_from_slice(&crc32(&chunk).to_be_bytes());
    }
    std::fs::write(&png, bytes).unwrap();
    assert_too_large(&too_large(&png, DEFAULT_MAX_CELLS), n, n, DEFAULT_MAX_CELLS);
    // A ROS map whose image is the huge PGM.
    let yaml = tmp("huge.yaml");
    std::fs::write(
        &yaml,
        "image: huge.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n\
         occupied_thresh: 0.65\nfree_thresh: 0.196\n",
    )
    .unwrap();
    assert_too_large(
        &too_large(&yaml, DEFAULT_MAX_CELLS),
        n,
        n,
        DEFAULT_MAX_CELLS,
    );
    let map = tmp("huge.map");
    std::fs::write(&map, format!("type octile\nheight {n}\nwidth {n}\nmap\n")).unwrap();
    assert_too_large(&too_large(&map, DEFAULT_MAX_CELLS), n, n, DEFAULT_MAX_CELLS);
}

/// The limit is the option's: a small map is refused under a smaller limit and loads
/// under its own size.
#[test]
fn the_limit_follows_the_option() {
    let map = tmp("small.map");
    std::fs::write(&map, "type octile\nheight 2\nwidth 3\nmap\n...\n.@.\n").unwrap();
    assert_too_large(&too_large(&map, 5), 3, 2, 5);
    let opts = LoadOptions {
        max_cells: 6,
        ..LoadOptions::default()
    };
    assert!(load_map(&map, &opts).is_ok());
    let pgm = tmp("small.pgm");
    std::fs::write(&pgm, "P2\n3 2\n255\n0 255 255\n255 255 255\n").unwrap();
    assert_too_large(&too_large(&pgm, 5), 3, 2, 5);
}

/// CRC-32 (IEEE) for the PNG chunk above.
fn crc32(data: &[u8]) -> u32 {
    let mut crc = 0xffff_ffffu32;
    for &b in data {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 != 0 {
                (crc >> 1) ^ 0xedb8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}
