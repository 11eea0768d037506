//! # rolldyn-rating — rating life of radial roller bearings
//!
//! Pure formulas, each one function citing its clause; SI in and out (the standards' N–mm
//! forms are converted inside):
//!
//! | module | content | source |
//! |---|---|---|
//! | [`geometry`] | the internal dimensions the ratings take | ISO 281:2007 §3 |
//! | [`iso281`] | C_r, P, L10, a1, ν1, κ, e_C, C_u, a_ISO, L_nm | ISO 281:2007 §7, §9, Annex B |
//! | [`iso76`] | C0r, P0r, s0 | ISO 76:2006 §6, §7 |
//! | [`ts16281`] | lamina ratings and equivalent loads, ring and bearing reference life L10r | ISO/TS 16281:2008 |
//! | [`duty`] | duty cycles: Palmgren–Miner | ISO 281:2007 §9.5 (Miner) |

// Validation reads `!(x > 0.0)` on purpose: it is also true for NaN, which must be rejected.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod duty;
pub mod geometry;
pub mod iso281;
pub mod iso76;
pub mod ts16281;

pub use geometry::RollerBearingGeometry;

/// A rating input outside the range a standard covers.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RatingError {
    /// An input outside the range of the standard's table or equations, with the reason.
    #[error("{0}")]
    OutOfRange(String),
}
