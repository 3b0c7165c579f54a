//! `Picture`: an 8-bit grey or RGB raster as image files store it (top row first).

/// An 8-bit raster with 1 (grey) or 3 (RGB) channels, **top row first**, as image files
/// and viewers store it: pixel `(x, y)` is column `x`, row `y` counted from the top.
///
/// The pipeline turns it into map cells with a vertical flip: pixel `(x, y)` becomes map
/// cell `(x, height - 1 - y)`.
///
/// ```
/// use envmap::Picture;
/// let pic = Picture::grey(2, 1, vec![0, 255]).unwrap();
/// assert_eq!(pic.luminance(1, 0), 255);
/// ```
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct Picture {
    width: usize,
    height: usize,
    channels: usize,
    data: Vec<u8>,
}

hyplan_core::grid_size!(Picture);

impl Picture {
    /// A grey picture, one byte per pixel, top row first; `None` on a length mismatch.
    #[must_use]
    pub fn grey(width: usize, height: usize, data: Vec<u8>) -> Option<Self> {
        Self::with_channels(width, height, 1, data)
    }

    /// An RGB picture, three bytes per pixel, top row first; `None` on a length mismatch.
    #[must_use]
    pub fn rgb(width: usize, height: usize, data: Vec<u8>) -> Option<Self> {
        Self::with_channels(width, height, 3, data)
    }

    fn with_channels(width: usize, height: usize, channels: usize, data: Vec<u8>) -> Option<Self> {
        let n = width.checked_mul(height)?.checked_mul(channels)?;
        (n == data.len()).then_some(Self {
            width,
            height,
            channels,
            data,
        })
    }

    /// A picture of `width x height` RGB pixels, all `colour`.
    #[must_use]
    pub fn filled_rgb(width: usize, height: usize, colour: [u8; 3]) -> Self {
        let data = colour.repeat(width * height);
        Self {
            width,
            height,
            channels: 3,
            data,
        }
    }

    /// 1 (grey) or 3 (RGB).
    #[must_use]
    pub const fn channels(&self) -> usize {
        self.channels
    }

    /// The bytes, top row first, `channels` bytes per pixel.
    #[must_use]
    pub fn data(&self) -> &[u8] {
        &self.data
    }

    /// The channels of pixel `(x, y)` (row `y` from the top); `x < width`, `y < height`.
    #[must_use]
    pub fn pixel(&self, x: usize, y: usize) -> &[u8] {
        let k = (y * self.width + x) * self.channels;
        &self.data[k..k + self.channels]
    }

    /// Sets pixel `(x, y)` to an RGB colour (grey pictures take its luminance); ignored
    /// outside the picture.
    pub fn set_rgb(&mut self, x: usize, y: usize, colour: [u8; 3]) {
        if x >= self.width || y >= self.height {
            return;
        }
        let k = (y * self.width + x) * self.channels;
        if self.channels == 3 {
            self.data[k..k + 3].copy_from_slice(&colour);
        } else {
            self.data[k] = luma(colour[0], colour[1], colour[2]);
        }
    }

    /// Luminance of pixel `(x, y)`: the grey value, or Rec. 709 luma
    /// `(2126 R + 7152 G + 722 B) / 10000` (rounded) for RGB, as the `image` crate computes it.
    #[must_use]
    pub fn luminance(&self, x: usize, y: usize) -> u8 {
        let p = self.pixel(x, y);
        if self.channels == 1 {
            p[0]
        } else {
            luma(p[0], p[1], p[2])
        }
    }

    /// Mean of the channels of pixel `(x, y)`, in `[0, 255]`: the "shade" ROS `map_server`
    /// thresholds.
    #[must_use]
    pub fn channel_mean(&self, x: usize, y: usize) -> f64 {
        let p = self.pixel(x, y);
        p.iter().map(|&c| f64::from(c)).sum::<f64>() / p.len() as f64
    }
}

/// Rec. 709 luma of an sRGB triple, rounded.
pub(crate) fn luma(r: u8, g: u8, b: u8) -> u8 {
    let y = 2126 * u32::from(r) + 7152 * u32::from(g) + 722 * u32::from(b);
    ((y + 5000) / 10000) as u8
}
