//! SPEC V-10, V-11, V-12 and the Fig. 2.10 trend — PAO1 ISO VG 320 with the Muraki model.
//!
//! Common assumptions (not in the seeds, SPEC V-12 derived cross-check): AISI 52100 E = 210 GPa,
//! ν = 0.3; oil density 850 kg/m³ (F-25); steel ρ_m = 7830 kg/m³ (F-25 proposal, default);
//! p̄ = ⅔ p_max, b = Hertz radius for the ball; film (2.19) with k = 1 (Auto); smooth surfaces
//! (the Fig. 2.8 curves are full-film μ_hd curves).
mod common;
use common::*;
use rolldyn_lubrication::*;

fn pao1() -> TractionModel {
    TractionModel::muraki(lubricant_by_name("pao1-vg320").unwrap()).unwrap()
}

/// V-12: computed s_cr = 0.16 (seed), experiment 0.19; SPEC acceptance 0.16 ± 0.02.
/// Obtained 0.1706 (+6.6 % vs the seed's computed value, −10 % vs experiment), μ_max = 0.0437
/// (SPEC derived ≈ 0.044). The residual difference to 0.16 is attributable to inputs the seed does
/// not give (oil density, elastic constants, which film formula/central vs minimum film) — no
/// constant was tuned. With the literal ρ_m = 830 kg/m³ the model gives 0.107, i.e. the F-25 reading
/// (7830) is the one consistent with the seed's 0.16.
#[test]
fn v12_critical_slip_40c() {
    let st = ball_on_disc(1e9, 2.5, 0.0, 40.0);
    let cs = critical_slip(&st, &pao1(), &SlipSearch::default()).unwrap();
    let s = cs.slip().expect("PAO1 at 40 °C has a thermal zone");
    assert!((s - 0.16).abs() <= 0.02, "s_cr = {s}");
    assert!((cs.coefficient().unwrap() - 0.044).abs() < 0.002);
    // the literal seed density ρ_m = 830 kg/m³ gives ≈ 0.11 (SPEC V-12 derived) — outside 0.16 ± 0.02
    let lit = TractionModel::lubricated(
        lubricant_by_name("pao1-vg320").unwrap(),
        MurakiSettings {
            solid: SolidThermal::SEED_000_LITERAL,
            ..Default::default()
        },
    )
    .unwrap();
    let s830 = critical_slip(&st, &lit, &SlipSearch::default())
        .unwrap()
        .slip()
        .unwrap();
    assert!((s830 - 0.11).abs() < 0.01, "{s830}");
    // Fig. 2.13: without self-heating the curve differs mainly in the thermal zone: in the linear
    // zone (s = 0.003) the two agree within 2 %, at s = 0.5 the isothermal one is > 1.5× higher and
    // has no maximum up to s = 2.
    let iso = TractionModel::lubricated(
        lubricant_by_name("pao1-vg320").unwrap(),
        MurakiSettings {
            rheology: Rheology::Isothermal,
            ..Default::default()
        },
    )
    .unwrap();
    let m = pao1();
    let f =
        |mdl: &TractionModel, s: f64| traction(&ball_on_disc(1e9, 2.5, s, 40.0), mdl).coefficient;
    assert!((f(&iso, 0.003) / f(&m, 0.003) - 1.0).abs() < 0.02);
    assert!(f(&iso, 0.5) > 1.5 * f(&m, 0.5));
    assert!(
        critical_slip(&st, &iso, &SlipSearch::default())
            .unwrap()
            .slip()
            .is_none()
    );
}

/// V-10 (Fig. 2.8 shape, 1 GPa, 2.5 m/s, 40…100 °C): every curve rises from 0 (linear zone),
/// reaches a maximum, then falls (thermal zone); the curves are ordered by temperature (hotter oil →
/// lower traction at fixed slip and lower maximum). Figure only in the seed: shape checks.
/// Fig. 2.10 trend: s_cr(T) obtained 0.171 / 0.242 / 0.326 / 0.544 / 0.878 at 40/50/60/80/100 °C —
/// increasing with temperature (the seed's figure has no numbers; the direction follows from
/// s_cr ≈ const/((β0 + κp̄) ζ τ0 u) with τ0 falling with T).
#[test]
fn v10_curve_shapes_and_fig_2_10_trend() {
    let m = pao1();
    let temps = [40.0, 50.0, 60.0, 80.0, 100.0];
    let mut prev_scr = 0.0;
    let mut prev_max = f64::INFINITY;
    let mut prev_mu_at_005 = f64::INFINITY;
    for t in temps {
        let st = ball_on_disc(1e9, 2.5, 0.0, t);
        let cs = critical_slip(&st, &m, &SlipSearch::default()).unwrap();
        let (scr, mmax) = (cs.slip().unwrap(), cs.coefficient().unwrap());
        let mu = |s: f64| traction(&ball_on_disc(1e9, 2.5, s, t), &m).coefficient;
        // rises: monotone on a log grid up to s_cr
        let mut last = 0.0;
        for k in 0..20 {
            let s = 1e-4 * (scr / 1e-4).powf(k as f64 / 20.0);
            let v = mu(s);
            assert!(v > last, "{t} °C: not rising at s = {s}");
            last = v;
        }
        // falls after the maximum
        let s_after = (2.0 * scr).min(2.0);
        assert!(mu(s_after) < mmax, "{t} °C: no thermal zone");
        assert!(mu(1e-6) < 1e-4, "linear zone starts at 0");
        assert!(
            scr > prev_scr,
            "s_cr must increase with T (Fig. 2.10 model curve)"
        );
        assert!(mmax < prev_max, "μ_max decreases with T");
        assert!(mu(0.05) < prev_mu_at_005);
        prev_scr = scr;
        prev_max = mmax;
        prev_mu_at_005 = mu(0.05);
    }
}

/// V-11 (Figs. 2.9, 2.11): inner raceway Ø180 mm, roller Ø21 mm, 530 rpm (u = 2.76 m/s in the cage
/// frame), 40/50/60/80/100 °C: s_cr decreases with p_max at every temperature. The film is (2.17)
/// (Auto for line contacts, as [000]); b and p̄ from (2.15)/(2.16). Trend only (no numbers in the seed).
#[test]
fn v11_scr_decreases_with_pressure() {
    let m = pao1();
    let u = inner_rolling_speed(530.0, 0.09, 0.021);
    assert!((u - 2.761).abs() < 0.01);
    for t in [40.0, 50.0, 60.0, 80.0, 100.0] {
        let mut prev = f64::INFINITY;
        for p in [0.6e9, 0.8e9, 1.0e9, 1.25e9, 1.5e9, 2.0e9] {
            let st = roller_inner(p, 0.0105, 0.09, 0.01, u, 0.0, t);
            let s = critical_slip(&st, &m, &SlipSearch::default())
                .unwrap()
                .slip();
            let s = s.unwrap_or_else(|| panic!("no maximum at {t} °C, {p} Pa"));
            assert!(s < prev, "{t} °C: s_cr({p}) = {s} not below {prev}");
            prev = s;
        }
    }
}
