//! The wear coefficient k as a function of the film parameter Λ (seed 000 §2.4, Fig. 2.18,
//! eq. 2.33; flag F-50; docs/theory.md §8.2).

pub use crate::law::WearLawError;
use serde::{Deserialize, Serialize};

/// Points (Λ, k) the seed reads off its Fig. 2.18 (seed 000 §3.1.1.5–3.1.1.7, §3.2.2, Table 3.6).
pub const SEED_POINTS: [(f64, f64); 4] = [
    (0.62, 3.57e-10),
    (0.75, 2.52342e-10),
    (0.762, 2.3e-10),
    (2.5, 4.55e-11),
];

/// Range of k under film (hydrodynamic) friction, "approximately 1e-11 to 5e-10" (seed 000 §2.4).
pub const SEED_FILM_K_RANGE: (f64, f64) = (1e-11, 5e-10);

/// k under boundary friction of hardened bearing steels: the seed's geometric mean of the
/// literature range 1e-10 … 5e-9 (√(1e-10 · 5e-9) = 7.07e-10, seed 000 §3.1.1.7).
pub const SEED_BOUNDARY_K: f64 = 7.1e-10;

/// Reference point of the power-law mode: the tapered end–rib contact (seed 000 Table 3.6).
pub const SEED_POWER_LAW_REFERENCE: (f64, f64) = (0.75, 2.52342e-10);

/// Λ below which the contact counts as boundary friction: the lower end of the range Λ = 0.4 … 2.4
/// in which the seed states k ∝ Λ⁻² (eq. 2.33); below it the seed gives no film-friction k.
pub const DEFAULT_BOUNDARY_LAMBDA: f64 = 0.4;

/// Exponent of k(Λ) outside the points, k ∝ Λ⁻² (seed 000 eq. 2.33).
const OUTER_EXPONENT: f64 = -2.0;

/// k(Λ): monotone piecewise-linear interpolation in (ln Λ, ln k) through points, k ∝ Λ⁻² outside
/// them, clamped to [k_min, k_max]; plus the boundary-friction k (SPEC §6.2, F-50). The power-law
/// mode k_ref (Λ/Λ_ref)⁻² is the table of the single point (Λ_ref, k_ref).
///
/// In a model file every field is optional (default: [`WearCoefficient::seed_default`]) and the
/// values are checked as [`WearCoefficient::from_points`] checks them.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "WearCoefficientFields")]
pub struct WearCoefficient {
    /// (Λ, k) with Λ increasing and k not increasing.
    points: Vec<(f64, f64)>,
    k_min: f64,
    k_max: f64,
    boundary_k: f64,
    boundary_lambda: f64,
}

/// The fields as a model file gives them, before validation.
#[derive(Deserialize)]
#[serde(default, deny_unknown_fields)]
struct WearCoefficientFields {
    points: Vec<(f64, f64)>,
    k_min: f64,
    k_max: f64,
    boundary_k: f64,
    boundary_lambda: f64,
}

impl Default for WearCoefficientFields {
    fn default() -> Self {
        let WearCoefficient {
            points,
            k_min,
            k_max,
            boundary_k,
            boundary_lambda,
        } = WearCoefficient::seed_default();
        Self {
            points,
            k_min,
            k_max,
            boundary_k,
            boundary_lambda,
        }
    }
}

impl TryFrom<WearCoefficientFields> for WearCoefficient {
    type Error = WearLawError;
    fn try_from(fields: WearCoefficientFields) -> Result<Self, WearLawError> {
        WearCoefficient::from_points(fields.points, fields.boundary_k)?
            .with_clamp(fields.k_min, fields.k_max)?
            .with_boundary_lambda(fields.boundary_lambda)
    }
}

impl Default for WearCoefficient {
    fn default() -> Self {
        Self::seed_default()
    }
}

impl WearCoefficient {
    /// The four seed points, clamp [1e-11, 5e-10], boundary k 7.1e-10, boundary below Λ = 0.4.
    pub fn seed_default() -> Self {
        Self::unchecked(SEED_POINTS.to_vec(), SEED_BOUNDARY_K)
    }

    /// Alternative mode k_ref (Λ/Λ_ref)⁻² (SPEC §6.2; the seed's reference is
    /// [`SEED_POWER_LAW_REFERENCE`]), with the seed's clamp and boundary k.
    ///
    /// # Panics
    /// When `k_ref` or `lambda_ref` is not positive and finite (a programming error; checked
    /// input goes through [`WearCoefficient::from_points`]).
    pub fn power_law(k_ref: f64, lambda_ref: f64) -> Self {
        Self::from_points(vec![(lambda_ref, k_ref)], SEED_BOUNDARY_K)
            .unwrap_or_else(|error| panic!("power-law wear coefficient: {error}"))
    }

    /// A table through `points` (Λ, k) with boundary k `boundary` and the seed's clamp; Λ must
    /// increase and k must not, all values positive and finite.
    pub fn from_points(points: Vec<(f64, f64)>, boundary: f64) -> Result<Self, WearLawError> {
        check_points(&points)?;
        check_positive("boundary_k", boundary)?;
        Ok(Self::unchecked(points, boundary))
    }

    /// The same table clamped to [k_min, k_max] instead.
    pub fn with_clamp(self, k_min: f64, k_max: f64) -> Result<Self, WearLawError> {
        check_positive("k_min", k_min)?;
        check_positive("k_max", k_max)?;
        if k_min > k_max {
            return Err(WearLawError::EmptyClamp { k_min, k_max });
        }
        Ok(Self {
            k_min,
            k_max,
            ..self
        })
    }

    /// The same table with boundary friction below `boundary_lambda` instead (0 allowed: only the
    /// dynamics' boundary flag and an unknown Λ then select the boundary k).
    pub fn with_boundary_lambda(self, boundary_lambda: f64) -> Result<Self, WearLawError> {
        if !(boundary_lambda.is_finite() && boundary_lambda >= 0.0) {
            return Err(WearLawError::NonPositive {
                name: "boundary_lambda",
                value: boundary_lambda,
            });
        }
        Ok(Self {
            boundary_lambda,
            ..self
        })
    }

    fn unchecked(points: Vec<(f64, f64)>, boundary_k: f64) -> Self {
        Self {
            points,
            k_min: SEED_FILM_K_RANGE.0,
            k_max: SEED_FILM_K_RANGE.1,
            boundary_k,
            boundary_lambda: DEFAULT_BOUNDARY_LAMBDA,
        }
    }

    /// k under film friction at Λ: k_min for Λ = +∞ (smooth surfaces), NaN for NaN.
    pub fn film(&self, lambda: f64) -> f64 {
        self.unclamped(lambda).clamp(self.k_min, self.k_max)
    }

    /// k under boundary friction.
    pub fn boundary(&self) -> f64 {
        self.boundary_k
    }

    /// Λ below which [`WearCoefficient::for_contact`] takes the boundary k.
    pub fn boundary_lambda(&self) -> f64 {
        self.boundary_lambda
    }

    /// The (Λ, k) points of the table.
    pub fn points(&self) -> &[(f64, f64)] {
        &self.points
    }

    /// The clamp [k_min, k_max] of the film k.
    pub fn clamp_range(&self) -> (f64, f64) {
        (self.k_min, self.k_max)
    }

    /// k for a contact: boundary k when `boundary` (the dynamics reports the end–rib regime) or
    /// Λ is NaN or below the boundary limit, else film(Λ) (Λ = +∞ is film friction).
    pub fn for_contact(&self, lambda: f64, boundary: bool) -> f64 {
        if boundary || lambda.is_nan() || lambda < self.boundary_lambda {
            self.boundary_k
        } else {
            self.film(lambda)
        }
    }

    /// The table without the clamp: power law through the two neighbouring points, Λ⁻² beyond
    /// the first and the last point.
    fn unclamped(&self, lambda: f64) -> f64 {
        let above = self.points.partition_point(|point| point.0 <= lambda);
        let (from, exponent) = match above {
            0 => (self.points[0], OUTER_EXPONENT),
            n if n == self.points.len() => (self.points[n - 1], OUTER_EXPONENT),
            n => {
                let (a, b) = (self.points[n - 1], self.points[n]);
                (a, (b.1 / a.1).ln() / (b.0 / a.0).ln())
            }
        };
        from.1 * (lambda / from.0).powf(exponent)
    }
}

fn check_points(points: &[(f64, f64)]) -> Result<(), WearLawError> {
    if points.is_empty() {
        return Err(WearLawError::NoPoints);
    }
    for (index, &(lambda, k)) in points.iter().enumerate() {
        if !(lambda.is_finite() && lambda > 0.0 && k.is_finite() && k > 0.0) {
            return Err(WearLawError::NonPositivePoint { index, lambda, k });
        }
        if index == 0 {
            continue;
        }
        let (previous_lambda, previous_k) = points[index - 1];
        if lambda <= previous_lambda || k > previous_k {
            return Err(WearLawError::NotMonotone {
                index,
                lambda,
                k,
                previous_lambda,
                previous_k,
            });
        }
    }
    Ok(())
}

fn check_positive(name: &'static str, value: f64) -> Result<(), WearLawError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(WearLawError::NonPositive { name, value })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use rolldyn_lubrication::regime::film_parameter;

    const MICRON: f64 = 1e-6;

    fn log_grid(from: f64, to: f64, n: usize) -> impl Iterator<Item = f64> {
        (0..=n).map(move |i| from * (to / from).powf(i as f64 / n as f64))
    }

    #[test]
    fn default_table_passes_through_the_four_seed_points_exactly() {
        let k = WearCoefficient::seed_default();
        for (lambda, seed_k) in SEED_POINTS {
            assert_eq!(k.film(lambda), seed_k, "Λ = {lambda}");
        }
    }

    #[test]
    fn default_table_is_monotone_and_inside_the_film_range() {
        let k = WearCoefficient::seed_default();
        let values: Vec<f64> = log_grid(0.05, 50.0, 400).map(|l| k.film(l)).collect();
        assert!(values.windows(2).all(|w| w[1] <= w[0]));
        assert!(values.iter().all(|v| (1e-11..=5e-10).contains(v)));
    }

    #[test]
    fn outside_the_points_k_falls_as_lambda_to_the_minus_two() {
        // seed 000 eq. 2.33; inside the clamp on both sides
        let k = WearCoefficient::seed_default();
        assert_relative_eq!(k.film(5.0), 4.55e-11 / 4.0, max_relative = 1e-12);
        assert_relative_eq!(k.film(4.0) / k.film(3.0), (4.0_f64 / 3.0).powi(-2));
        assert_relative_eq!(k.film(0.55), 3.57e-10 * (0.55_f64 / 0.62).powi(-2));
    }

    #[test]
    fn film_k_is_clamped_to_the_seed_range() {
        let k = WearCoefficient::seed_default();
        assert_eq!(k.film(0.3), 5e-10);
        assert_eq!(k.film(0.0), 5e-10);
        assert_eq!(k.film(20.0), 1e-11);
        assert_eq!(k.film(f64::INFINITY), 1e-11);
        let narrow = k.with_clamp(4e-11, 3e-10).unwrap();
        assert_eq!(narrow.film(0.62), 3e-10);
        assert_eq!(narrow.film(2.5), 4.55e-11);
        assert_eq!(narrow.film(3.0), 4e-11);
    }

    #[test]
    fn power_law_mode_gives_the_table_3_6_value_at_0_75() {
        let (lambda_ref, k_ref) = SEED_POWER_LAW_REFERENCE;
        let k = WearCoefficient::power_law(k_ref, lambda_ref);
        assert_eq!(k.film(0.75), 2.52342e-10);
        assert_relative_eq!(k.film(1.5), 2.52342e-10 / 4.0, max_relative = 1e-12);
    }

    #[test]
    fn grease_starvation_film_minus_30_percent_doubles_k() {
        // SPEC §6.2: film −30 % → k × 0.7⁻² = 2.04 under k ∝ Λ⁻²
        let power = WearCoefficient::power_law(2.52342e-10, 0.75);
        assert_relative_eq!(
            power.film(0.7 * 1.5) / power.film(1.5),
            2.0408,
            max_relative = 1e-4
        );
        let table = WearCoefficient::seed_default();
        assert_relative_eq!(
            table.film(0.7 * 4.0) / table.film(4.0),
            2.0408,
            max_relative = 1e-4
        );
        // between the seed points 0.762 and 2.5 the table falls as Λ^-1.364: ×1.63 only
        let inside = table.film(0.7 * 2.4) / table.film(2.4);
        println!("starvation factor between the seed points (Λ 2.4 → 1.68): {inside:.3}");
        assert_relative_eq!(inside, 0.7_f64.powf(-1.3639), max_relative = 1e-3);
    }

    #[test]
    fn boundary_k_for_flagged_unknown_or_thin_films() {
        let k = WearCoefficient::seed_default();
        assert_eq!(k.boundary(), 7.1e-10);
        assert_eq!(k.for_contact(2.5, true), 7.1e-10);
        assert_eq!(k.for_contact(f64::NAN, false), 7.1e-10);
        assert_eq!(k.for_contact(0.3, false), 7.1e-10);
        assert_eq!(k.for_contact(2.5, false), 4.55e-11);
        assert_eq!(k.for_contact(f64::INFINITY, false), 1e-11);
        let film_only = k.with_boundary_lambda(0.0).unwrap();
        assert_eq!(film_only.for_contact(0.3, false), 5e-10);
    }

    #[test]
    fn invalid_tables_are_rejected_naming_the_value() {
        let error =
            WearCoefficient::from_points(vec![(0.5, 1e-10), (1.0, 2e-10)], 7.1e-10).unwrap_err();
        assert!(matches!(error, WearLawError::NotMonotone { index: 1, .. }));
        assert!(error.to_string().contains("2e-10"), "{error}");
        let error = WearCoefficient::from_points(vec![(1.0, 1e-10), (1.0, 1e-11)], 7.1e-10);
        assert!(matches!(error, Err(WearLawError::NotMonotone { .. })));
        let error = WearCoefficient::from_points(vec![(-0.5, 1e-10)], 7.1e-10).unwrap_err();
        assert!(error.to_string().contains("-0.5"), "{error}");
        assert_eq!(
            WearCoefficient::from_points(vec![], 7.1e-10),
            Err(WearLawError::NoPoints)
        );
        assert!(WearCoefficient::from_points(vec![(1.0, 1e-10)], 0.0).is_err());
        let clamp = WearCoefficient::seed_default().with_clamp(5e-10, 1e-11);
        assert!(matches!(clamp, Err(WearLawError::EmptyClamp { .. })));
    }

    #[test]
    fn model_file_fields_default_to_the_seed_and_are_checked() {
        let given: WearCoefficient = toml::from_str("k_max = 4e-10").unwrap();
        assert_eq!(
            given,
            WearCoefficient::seed_default()
                .with_clamp(1e-11, 4e-10)
                .unwrap()
        );
        let round_trip: WearCoefficient =
            toml::from_str(&toml::to_string(&WearCoefficient::seed_default()).unwrap()).unwrap();
        assert_eq!(round_trip, WearCoefficient::seed_default());
        assert!(
            toml::from_str::<WearCoefficient>("points = [[1.0, 1e-10], [2.0, 3e-10]]").is_err()
        );
        assert!(toml::from_str::<WearCoefficient>("k_maximum = 4e-10").is_err());
    }

    #[test]
    fn v19_surface_finish_ratio_of_bar_wear_for_ra_2_5_and_0_8_um() {
        // seed 000 §3.1.1.5: h = 2.4 µm, roller Ra 0.16 µm; bar Ra 2.5 → 0.8 µm reduces the wear
        // "≈ 11 times". Λ by seed 000 (1.2) (the workspace's one definition), p and v unchanged,
        // so the wear ratio is the k ratio.
        let h = 2.4 * MICRON;
        let rough = film_parameter(h, 2.5 * MICRON, 0.16 * MICRON);
        let fine = film_parameter(h, 0.8 * MICRON, 0.16 * MICRON);
        assert_relative_eq!(rough, 0.7664, max_relative = 1e-3);
        assert_relative_eq!(fine, 2.3534, max_relative = 1e-3);
        let table = WearCoefficient::seed_default();
        let (lambda_ref, k_ref) = SEED_POWER_LAW_REFERENCE;
        let power = WearCoefficient::power_law(k_ref, lambda_ref);
        let table_ratio = table.film(rough) / table.film(fine);
        let power_ratio = power.film(rough) / power.film(fine);
        println!(
            "V-19 finish: Λ {rough:.4} → {fine:.4}; k ratio default table {table_ratio:.3}, \
             Λ^-2 mode {power_ratio:.3} (seed ≈ 11)"
        );
        // both Λ lie between the seed points 0.762 and 2.5: the table falls as Λ^-1.364 there
        let slope = (4.55e-11_f64 / 2.3e-10).ln() / (2.5_f64 / 0.762).ln();
        assert_relative_eq!(
            table_ratio,
            (fine / rough).powf(-slope),
            max_relative = 1e-12
        );
        assert_relative_eq!(table_ratio, 4.62, max_relative = 1e-2);
        // Λ⁻²: (Ra₁² + Ra₂²) ratio of the two finishes, 6.2756 / 0.6656
        assert_relative_eq!(power_ratio, 6.2756 / 0.6656, max_relative = 1e-9);
    }
}
