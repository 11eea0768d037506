//! Minimal 3-vector helpers on `[f64; 3]` (no dependency, inlined, allocation-free).

/// A 3-vector in SI units.
pub type V3 = [f64; 3];

#[inline]
pub(crate) fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
#[inline]
pub(crate) fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
#[inline]
pub(crate) fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
#[inline]
pub(crate) fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
#[inline]
pub(crate) fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
#[inline]
pub(crate) fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}
/// `a + s b`.
#[inline]
pub(crate) fn axpy(a: V3, s: f64, b: V3) -> V3 {
    [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]]
}
/// Unit vector (returns `fallback` for a zero vector).
#[inline]
pub(crate) fn unit_or(a: V3, fallback: V3) -> V3 {
    let n = norm(a);
    if n > 0.0 { scale(a, 1.0 / n) } else { fallback }
}
/// Component of `a` perpendicular to the unit vector `u`.
#[inline]
pub(crate) fn perp(a: V3, u: V3) -> V3 {
    axpy(a, -dot(a, u), u)
}

/// `x^n` for `x > 0` as `exp(n ln x)`: ≈ 40 % cheaper than `powf` in the contact loops (11 vs
/// 19 ns measured), relative error ≲ |n ln x|·ε ≈ 2·10⁻¹⁵ at contact approaches. (The branch-free
/// `rolldyn_numerics::fastmath` versions are slower for single values; the raceway slices use
/// them inside the vectorised slice kernel, `crate::slice_kernel`.)
#[inline]
pub(crate) fn power(x: f64, n: f64) -> f64 {
    (n * x.ln()).exp()
}
