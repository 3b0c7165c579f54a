//! Public-API tests of `postproc`, as one binary.

mod errors;
mod grid;
mod paths;
mod pchip_props;
mod prune_props;
mod scipy;
mod smooth_props;
mod spline_props;
mod timing_props;

/// With the `serde` feature, methods serialise as their command-line names.
#[cfg(feature = "serde")]
#[test]
fn serde_uses_the_names() {
    for m in postproc::Smoothing::ALL {
        let json = serde_json::to_string(&m).unwrap();
        assert_eq!(json, format!("\"{}\"", m.name()));
        assert_eq!(
            serde_json::from_str::<postproc::Smoothing>(&json).unwrap(),
            m
        );
    }
    let l = postproc::Limits::new(0.15, 1.0, 0.2).unwrap();
    let back: postproc::Limits = serde_json::from_str(&serde_json::to_string(&l).unwrap()).unwrap();
    assert_eq!(back, l);
}
