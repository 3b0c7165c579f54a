//! Stage 1 of the seed-000 pipeline: binarize a picture into an obstacle mask.

use crate::{Mask, Picture};

/// The obstacle mask of a picture: pixel `(x, y)` is an obstacle when its
/// [luminance](Picture::luminance) is **below** `threshold` (dark furniture on a light
/// floor, the top-view pictures hyplan is fed), or, with `invert`, when it is **at least**
/// `threshold` (bright = obstacle, e.g. a height image where tall means bright).
///
/// Seed `000_9b224721fe327833.txt`, section 4.1, extracts obstacles from a Kinect height
/// image with the threshold 100; [`Pipeline`](crate::Pipeline) uses 100 by default too.
///
/// The mask is in map cells: pixel `(x, y)` (row `y` from the top) is cell
/// `(x, height - 1 - y)`.
///
/// ```
/// use envmap::{binarize, Picture};
/// // Top row: black, white. Bottom row: grey 99, grey 100.
/// let pic = Picture::grey(2, 2, vec![0, 255, 99, 100]).unwrap();
/// let mask = binarize(&pic, 100, false);
/// assert!(mask.get(0, 1) && !mask.get(1, 1));  // top row
/// assert!(mask.get(0, 0) && !mask.get(1, 0));  // 99 < 100 <= 100
/// assert_eq!(binarize(&pic, 100, true).count(), 2);
/// ```
#[must_use]
pub fn binarize(picture: &Picture, threshold: u8, invert: bool) -> Mask {
    let (w, h) = (picture.width(), picture.height());
    let mut cells = vec![false; w * h];
    let data = picture.data();
    let ch = picture.channels();
    for y in 0..h {
        let j = h - 1 - y;
        let src = &data[y * w * ch..(y + 1) * w * ch];
        let dst = &mut cells[j * w..(j + 1) * w];
        if ch == 1 {
            for (d, &v) in dst.iter_mut().zip(src) {
                *d = (v < threshold) != invert;
            }
        } else {
            for (d, p) in dst.iter_mut().zip(src.chunks_exact(ch)) {
                *d = (crate::picture::luma(p[0], p[1], p[2]) < threshold) != invert;
            }
        }
    }
    Mask::from_cells(w, h, cells).expect("w * h cells by construction")
}
