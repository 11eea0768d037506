//! Cavitation models (SPEC §8.1 (002-1.13) and proposal; §8.6 (4.6), (4.32)).

/// How negative gauge pressures are treated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Cavitation {
    /// Full Sommerfeld: the linear Reynolds equation everywhere, sub-ambient pressures allowed
    /// (the "COMSOL without cavitation" case of seed 002 §4.7).
    None,
    /// Reynolds / Swift–Stieber condition as a linear complementarity problem p ≥ p_cav,
    /// (A p − b) ≥ 0, (p − p_cav)(A p − b) = 0, solved exactly by a primal–dual active set on
    /// the direct solver. Equivalent to the seed's "project P < 0 → 0 and switch off the Couette
    /// source" (SPEC §8.1 proposal) at convergence. Default.
    #[default]
    Reynolds,
    /// Mass-conserving Jakobsson–Floberg–Olsson (Elrod) model: in the cavitated zone p = p_cav and
    /// the film fill fraction θ ∈ [0, 1] is transported by the Couette flux (upwinded), with
    /// complementarity (p − p_cav)(1 − θ) = 0. Solved by active-set iterations on the mixed
    /// (p, θ) unknowns.
    Jfo,
}
