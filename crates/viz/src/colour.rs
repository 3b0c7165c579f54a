//! Colours: RGBA bytes, written as SVG wants them.

/// A colour, red, green, blue, alpha (255: opaque).
pub type Rgba = [u8; 4];

/// `#rrggbb` of a colour (its alpha is written apart, see [`opacity`]).
///
/// ```
/// assert_eq!(viz::hex([220, 20, 20, 255]), "#dc1414");
/// ```
#[must_use]
pub fn hex(c: Rgba) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// The alpha of a colour as an SVG opacity in [0, 1].
///
/// ```
/// assert_eq!(viz::opacity([0, 0, 0, 255]), 1.0);
/// ```
#[must_use]
pub fn opacity(c: Rgba) -> f64 {
    f64::from(c[3]) / 255.0
}

/// An opaque colour from `#rgb` shorthand digits (each doubled: `rgb(0x3, 0x9, 0xf)` is
/// `#3399ff`), the form the simulator's figures were designed in.
///
/// ```
/// assert_eq!(viz::rgb(0x3, 0x9, 0xf), [0x33, 0x99, 0xff, 255]);
/// ```
#[must_use]
pub const fn rgb(r: u8, g: u8, b: u8) -> Rgba {
    [r * 17, g * 17, b * 17, 255]
}

/// The same colour with alpha `a` (0..=255).
///
/// ```
/// assert_eq!(viz::with_alpha([1, 2, 3, 255], 128), [1, 2, 3, 128]);
/// ```
#[must_use]
pub const fn with_alpha(c: Rgba, a: u8) -> Rgba {
    [c[0], c[1], c[2], a]
}
