//! Decoding any bytes as an image never panics, and small decoded pictures go through the
//! whole pipeline (binarize, components, rectangles, EDT, zones) without panicking.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(pic) = envmap::decode_picture(data, "fuzz.png".as_ref()) {
        assert!(pic.width() > 0 && pic.height() > 0);
        if pic.width() * pic.height() <= 1 << 16 {
            let threshold = data.first().copied().unwrap_or(100);
            let p = envmap::Pipeline {
                threshold,
                rectangles: data.len() % 2 == 0,
                safety_radius: 3.0,
                ..envmap::Pipeline::default()
            };
            let out = p.run(&pic).expect("valid parameters");
            assert_eq!(out.map.width(), pic.width());
        }
    }
});
