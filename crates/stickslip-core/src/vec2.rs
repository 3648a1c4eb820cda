//! Minimal 2-vector arithmetic for tangent-plane quantities.
//!
//! The friction state lives in the contact's tangent plane; a plain `[f64; 2]` keeps the core
//! free of any linear-algebra crate (the rapier crate converts to and from its own types in one
//! place).

/// A vector in the tangent plane, `[x, y]`.
pub type Vec2 = [f64; 2];

/// Euclidean norm.
#[inline]
pub fn norm(v: Vec2) -> f64 {
    // sqrt(x² + y²) is several times cheaper than libm's `hypot` (it is on the contact hook's
    // path); `hypot` only where the squares leave f64's normal range (below 1e-150 a zero
    // sum means a vector of at most 1e-154, i.e. zero).
    let n = (v[0] * v[0] + v[1] * v[1]).sqrt();
    if n == 0.0 || (1e-150..1e150).contains(&n) {
        n
    } else {
        v[0].hypot(v[1])
    }
}

/// `a + b`.
#[inline]
pub fn add(a: Vec2, b: Vec2) -> Vec2 {
    [a[0] + b[0], a[1] + b[1]]
}

/// `a - b`.
#[inline]
pub fn sub(a: Vec2, b: Vec2) -> Vec2 {
    [a[0] - b[0], a[1] - b[1]]
}

/// `s * v`.
#[inline]
pub fn scale(v: Vec2, s: f64) -> Vec2 {
    [v[0] * s, v[1] * s]
}

/// Dot product.
#[inline]
pub fn dot(a: Vec2, b: Vec2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

/// Unit vector along `v`, or `None` when `v` is (numerically) zero.
#[inline]
pub fn normalize(v: Vec2) -> Option<Vec2> {
    let n = norm(v);
    (n > 1e-300 && n.is_finite()).then(|| scale(v, 1.0 / n))
}

/// `v` scaled down so that its norm does not exceed `max` (`max >= 0`).
#[inline]
pub fn clamp_norm(v: Vec2, max: f64) -> Vec2 {
    let n = norm(v);
    if n > max && n > 0.0 {
        scale(v, max / n)
    } else {
        v
    }
}
