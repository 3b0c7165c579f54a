//! The ROS map YAML parser never panics; accepted metadata is in range.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(meta) = envmap::parse_ros_yaml(data, "fuzz/map.yaml".as_ref()) {
        assert!(meta.resolution.is_finite() && meta.resolution > 0.0);
        assert!((0.0..=1.0).contains(&meta.free_thresh));
        assert!(meta.free_thresh <= meta.occupied_thresh && meta.occupied_thresh <= 1.0);
        for shade in [0.0, 127.5, 205.0, 255.0] {
            let _ = meta.classify(shade);
        }
    }
});
