//! Surface waviness added to the film thickness (SPEC §8.6 input list: "small-scale waviness
//! parameters (surface waviness added to H — form not given, input function)").
//!
//! Implemented form (proposal): a sum of harmonics w(s) = Σ aₖ cos(κₖ s + φₖ) along the sliding
//! coordinate s (radians on a journal, metres on a line contact). Waviness carried by a surface
//! moving at speed u travels with it, w(s − u t), which adds the squeeze term ∂h/∂t = −u ∂w/∂s.

/// One harmonic a·cos(κ s + φ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaveHarmonic {
    /// Amplitude a, m (positive opens the gap at the crest).
    pub amplitude: f64,
    /// Wavenumber κ per unit of the coordinate (waves per revolution on a journal; 2π/λ on a line).
    pub wavenumber: f64,
    /// Phase φ, rad.
    pub phase: f64,
}

/// Which surface carries the waviness (decides whether it moves).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum WavySurface {
    /// Surface 1 (stationary bush of a journal bearing; the plate of a line contact).
    #[default]
    First,
    /// Surface 2 (the journal; the roller).
    Second,
}

/// Waviness of one surface.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Waviness {
    /// Harmonics.
    pub harmonics: Vec<WaveHarmonic>,
    /// Surface carrying it.
    pub surface: WavySurface,
}

impl Waviness {
    /// No waviness.
    pub fn none() -> Self {
        Self::default()
    }

    /// True without harmonics.
    pub fn is_empty(&self) -> bool {
        self.harmonics.is_empty()
    }

    /// w(s), m.
    pub fn value(&self, s: f64) -> f64 {
        self.harmonics
            .iter()
            .map(|h| h.amplitude * (h.wavenumber * s + h.phase).cos())
            .sum()
    }

    /// dw/ds.
    pub fn slope(&self, s: f64) -> f64 {
        self.harmonics
            .iter()
            .map(|h| -h.amplitude * h.wavenumber * (h.wavenumber * s + h.phase).sin())
            .sum()
    }

    /// ∂h/∂t contribution when the carrying surface moves at `speed` (coordinate units per s).
    pub fn squeeze(&self, s: f64, speed: f64) -> f64 {
        -speed * self.slope(s)
    }
}
