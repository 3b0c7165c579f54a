//! The MovingAI `.map` parser never panics; a parsed map has the header's size.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(map) = envmap::parse_movingai(data, "fuzz.map".as_ref()) {
        assert_eq!(map.zones().len(), map.width() * map.height());
        let [f, r, x] = map.zone_counts();
        assert_eq!(r, 0);
        assert_eq!(f + x, map.width() * map.height());
    }
});
