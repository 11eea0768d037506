//! The design rules of the internal geometry (docs/theory.md, "A model from a designation"):
//! each value is a [`Dim`] with its [`Basis`] — a standard's table, the user's input, an
//! estimate by a named rule, or a consequence of other values.

use crate::{DesignError, DesignInput, iso15, iso5753};
use std::f64::consts::PI;

/// Where a value comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum Basis {
    /// A standard's table or the user's input.
    Source(String),
    /// A design rule: an estimate, written `# ESTIMATED: …`.
    Estimated(String),
    /// Follows from other values, written `# DERIVED: …`.
    Derived(String),
}

/// A value (SI) and its basis.
#[derive(Clone, Debug, PartialEq)]
pub struct Dim {
    pub value: f64,
    pub basis: Basis,
}

fn source(value: f64, why: impl Into<String>) -> Dim {
    Dim {
        value,
        basis: Basis::Source(why.into()),
    }
}
fn estimated(value: f64, why: impl Into<String>) -> Dim {
    Dim {
        value,
        basis: Basis::Estimated(why.into()),
    }
}
fn derived(value: f64, why: impl Into<String>) -> Dim {
    Dim {
        value,
        basis: Basis::Derived(why.into()),
    }
}

const MM: f64 = 1e-3;

/// Roller diameter D_w ≈ 0.25 … 0.3 (D − d), the rule of thumb of issue 38 (after Harris &
/// Kotzalas, *Essential Concepts of Bearing Technology*; docs/theory.md §14.2 says what was and
/// was not checked); the middle of the range is taken.
pub const ROLLER_DIAMETER_FRACTION: f64 = 0.275;
/// Axial width of a rib, per side: the ring's chamfer r_s plus 0.2 D_w of rib face.
pub const RIB_FACE_PER_ROLLER_DIAMETER: f64 = 0.2;
/// Rib height above the raceway, 0.25 D_w: within the usual 0.2–0.35 D_w (Harris & Kotzalas,
/// *Essential Concepts of Bearing Technology*, 5th ed., §1.3, as `rolldyn_geometry`'s envelope
/// notes cite it), the rib face reaching past the roller's end chamfer to half its radius.
pub const RIB_HEIGHT_PER_ROLLER_DIAMETER: f64 = 0.25;
/// Cage bar width at the pitch circle at least 0.3 D_w (machined window cage); sets Z.
pub const BAR_PER_ROLLER_DIAMETER: f64 = 0.3;
/// Radial gap between the cage and the ring (or rib) it does not run on, 0.1 D_w.
pub const CAGE_GAP_PER_ROLLER_DIAMETER: f64 = 0.1;
/// Diametral floating clearance of the cage on its land, 0.3 % of the land diameter (the
/// seed bearings 2002834 and 1032930: 0.5 mm on Ø173 mm, 0.4 mm on Ø154.4 mm, 0.29 % and 0.26 %).
pub const FLOATING_CLEARANCE_PER_LAND_DIAMETER: f64 = 0.003;
/// The land-guidance design rule (docs/theory.md §1.6): the roller's play to a pocket wall is
/// 1.2 × the land's radial gap, so that the cage runs on its land, not on its rollers.
pub const LAND_GUIDANCE_PLAY_FACTOR: f64 = 1.2;
/// Roller–rib axial play, 1 % of D_w (total, between the two rib faces).
pub const RIB_PLAY_PER_ROLLER_DIAMETER: f64 = 0.01;
/// Retaining lip window, 0.9 D_w: narrower than the roller, so the cage holds it.
pub const LIP_WINDOW_PER_ROLLER_DIAMETER: f64 = 0.9;
/// Smallest radial thickness of a retaining lip, 0.1 D_w; a thinner lip is left out.
pub const LIP_MIN_THICKNESS_PER_ROLLER_DIAMETER: f64 = 0.1;
/// Oil temperature written when none is given, °C (named as ASSUMED in the file and warned).
pub const ASSUMED_OIL_TEMPERATURE_C: f64 = 70.0;

/// NHBB, *Engineering reference: Roller bearing features*, "Roller tolerances" table
/// (https://www.nhbb.com/knowledge-center/engineering-reference/ball-roller-bearings/roller-bearing-features):
/// rollers 5 mm and 22 mm; mid values of crown drop, flat length and corner, in mm.
const NHBB_ROLLERS: [(f64, f64, f64, f64); 2] = [
    // (size, crown drop, flat length, corner)
    (5.0, 0.0002 * 25.4, 0.090 * 25.4, 0.015 * 25.4),
    (22.0, 0.00083 * 25.4, 0.420 * 25.4, 0.035 * 25.4),
];
const NHBB: &str = "NHBB Engineering Reference \"Roller Bearing Features\", roller tolerance table (5 and 22 mm rollers)";
/// Raceway roughness: NHBB's roller-path surface finish 6 µin Ra.
const RACEWAY_RA_UM: f64 = 6.0 * 0.0254;

/// Linear interpolation (and extrapolation) in the roller size between NHBB's two rows.
fn nhbb(size_mm: f64, column: fn(&(f64, f64, f64, f64)) -> f64) -> f64 {
    let [a, b] = NHBB_ROLLERS;
    let t = (size_mm - a.0) / (b.0 - a.0);
    column(&a) + t * (column(&b) - column(&a))
}

fn round_to(x: f64, step: f64) -> f64 {
    (x / step).round() * step
}
fn floor_to(x: f64, step: f64) -> f64 {
    (x / step + 1e-9).floor() * step
}
fn mm(x: f64) -> String {
    let s = format!("{:.4}", x / MM);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    format!("{s} mm")
}

/// A retaining lip of the cage pocket.
#[derive(Clone, Debug, PartialEq)]
pub struct Lip {
    /// At the bore (`true`, outer-ring guided cages) or at the outside.
    pub at_bore: bool,
    pub diameter: Dim,
    pub window: Dim,
    pub tip_radius: Dim,
}

/// The designed bearing.
#[derive(Clone, Debug, PartialEq)]
pub struct BearingDesign {
    pub input: DesignInput,
    pub chamfer_min: Dim,
    pub roller_diameter: Dim,
    pub roller_length: Dim,
    pub roller_count: usize,
    pub roller_count_basis: Basis,
    pub pitch_diameter: Dim,
    pub clearance: Dim,
    pub inner_raceway: Dim,
    pub outer_raceway: Dim,
    /// Rim diameter of the two ribs of the guiding ring (outer ring for NU, NJ, NUP; inner for N).
    pub guiding_rib: Dim,
    /// Rim diameter of the ribs on the other ring (NJ, NUP).
    pub other_rib: Option<Dim>,
    pub rib_play: Dim,
    pub rib_spacing: Dim,
    pub land_width: Dim,
    pub floating_clearance: Dim,
    pub cage_bore: Dim,
    pub cage_outside: Dim,
    pub cage_width: Dim,
    pub pocket_axial: Dim,
    pub face_clearance: Dim,
    pub lip: Option<Lip>,
    /// Why there is no lip, when there is none.
    pub no_lip: Option<String>,
    pub fillet_radius: Dim,
    pub edge_break: Dim,
    pub crown_straight: Dim,
    pub crown_drop: Dim,
    pub roller_chamfer: Dim,
    pub raceway_ra: Dim,
    pub roller_ra: Dim,
    pub cage_ra: Dim,
    pub oil_temperature: Option<Dim>,
    /// Defaults that stand in for missing input, to be shown to the user.
    pub warnings: Vec<String>,
}

impl BearingDesign {
    /// The cage runs on the outer ring's ribs (NU, NJ, NUP) or on the inner ring's (N).
    pub fn outer_guided(&self) -> bool {
        self.input.ribs.outer_ribs()
    }
}

/// Designs the bearing: boundary dimensions as given, the internal geometry by the rules above.
pub fn design(input: &DesignInput) -> Result<BearingDesign, DesignError> {
    let b = &input.boundary;
    check_boundary(b)?;
    let chamfer_min = match b.chamfer_min {
        Some(r) => source(r, b.source.clone()),
        None => {
            let (series, row) = iso15::nearest(b.bore / MM, b.outside / MM, b.width / MM);
            estimated(
                row.chamfer_min_mm * MM,
                format!(
                    "r_s min of the nearest ISO 15 row {} × {} × {} mm ({})",
                    row.bore_mm,
                    row.outside_mm,
                    row.width_mm,
                    series.table()
                ),
            )
        }
    };
    let dw = roller_diameter(input)?;
    let d_w = dw.value;
    let rib_width = chamfer_min.value + RIB_FACE_PER_ROLLER_DIAMETER * d_w;
    let lw = roller_length(input, rib_width, d_w)?;
    let l_w = lw.value;
    let pitch = derived(0.5 * (b.bore + b.outside), "D_pw = (d + D)/2");
    let (clearance, clearance_range) = radial_clearance(input)?;
    let g_r = clearance.value;
    let inner_raceway = derived(
        pitch.value - d_w - 0.5 * g_r,
        "d_i = D_pw − D_w − G_r/2 (rollers on the pitch circle, clearance split evenly)",
    );
    let outer_raceway = derived(
        pitch.value + d_w + 0.5 * g_r,
        "D_o = D_pw + D_w + G_r/2, so that D_o − d_i − 2 D_w = G_r",
    );
    check_walls(b, inner_raceway.value, outer_raceway.value, input)?;
    let rib_height = RIB_HEIGHT_PER_ROLLER_DIAMETER * d_w;
    let rib_rule = format!(
        "rib height {} D_w = {} above the raceway (usual 0.2–0.35 D_w), theory §14.3",
        RIB_HEIGHT_PER_ROLLER_DIAMETER,
        mm(rib_height)
    );
    let outer = input.ribs.outer_ribs();
    let guiding_rib = if outer {
        estimated(outer_raceway.value - 2.0 * rib_height, rib_rule.clone())
    } else {
        estimated(inner_raceway.value + 2.0 * rib_height, rib_rule.clone())
    };
    let other_rib = match input.ribs.other_ring_ribs() {
        (false, false) => None,
        _ => Some(estimated(inner_raceway.value + 2.0 * rib_height, rib_rule)),
    };
    let rib_play = estimated(
        round_to(RIB_PLAY_PER_ROLLER_DIAMETER * d_w, 0.01 * MM).max(0.02 * MM),
        format!(
            "roller–rib axial play {} D_w, theory §14.3",
            RIB_PLAY_PER_ROLLER_DIAMETER
        ),
    );
    let rib_spacing = derived(l_w + rib_play.value, "L_w + roller–rib axial play");
    let land_width = derived(
        0.5 * (b.width - rib_spacing.value),
        "rib width (B − rib spacing)/2: the cage runs on the rib rims",
    );
    let floating_clearance = estimated(
        round_to(
            FLOATING_CLEARANCE_PER_LAND_DIAMETER * guiding_rib.value,
            0.05 * MM,
        )
        .max(0.1 * MM),
        format!(
            "{} % of the land diameter as the seed bearings 2002834, 1032930 (0.29 %, 0.26 %), theory §14.4",
            100.0 * FLOATING_CLEARANCE_PER_LAND_DIAMETER
        ),
    );
    let g = floating_clearance.value;
    let gap = round_to(CAGE_GAP_PER_ROLLER_DIAMETER * d_w, 0.1 * MM);
    let gap_rule = format!(
        "{} D_w = {} radial gap to the ring it does not run on, theory §14.4",
        CAGE_GAP_PER_ROLLER_DIAMETER,
        mm(gap)
    );
    let (cage_bore, cage_outside) = if outer {
        let below = other_rib
            .as_ref()
            .map_or(inner_raceway.value, |r| r.value.max(inner_raceway.value));
        (
            estimated(below + 2.0 * gap, gap_rule),
            derived(
                guiding_rib.value - g,
                "land (outer rib bore) − floating clearance",
            ),
        )
    } else {
        (
            derived(
                guiding_rib.value + g,
                "land (inner rib rim) + floating clearance",
            ),
            estimated(outer_raceway.value - 2.0 * gap, gap_rule),
        )
    };
    let face_clearance = derived(
        LAND_GUIDANCE_PLAY_FACTOR * g,
        format!(
            "land-guidance rule: play per side {} × the land gap g/2 (theory §1.6)",
            LAND_GUIDANCE_PLAY_FACTOR
        ),
    );
    let (roller_count, roller_count_basis) =
        roller_count(input, pitch.value, d_w, face_clearance.value)?;
    let pocket_axial = derived(
        l_w + 2.0 * rib_play.value,
        "L_w + 2 × roller–rib play: the ribs guide the rollers, not the pocket ends",
    );
    let cage_width = derived(
        b.width - 2.0 * chamfer_min.value,
        "B − 2 r_s: inside the rings' chamfers",
    );
    if cage_width.value <= pocket_axial.value {
        return Err(DesignError::new(
            "--roller-length",
            format!(
                "{} leaves no cage rim: the pocket {} is not narrower than the cage {}",
                mm(l_w),
                mm(pocket_axial.value),
                mm(cage_width.value)
            ),
        ));
    }
    let lip_play = LAND_GUIDANCE_PLAY_FACTOR * 0.5 * g + 0.5 * g_r;
    let (lip, no_lip) = retaining_lip(
        outer,
        0.5 * pitch.value,
        0.5 * d_w,
        lip_play,
        0.5 * cage_bore.value,
        0.5 * cage_outside.value,
    );
    let fillet_radius = estimated(
        round_to(0.03 * d_w, 0.1 * MM).max(0.2 * MM),
        "window-corner fillet 0.03 D_w, theory §14.4",
    );
    let size_mm = d_w / MM;
    let crown_straight = estimated(
        round_to(
            l_w * nhbb(size_mm, |r| r.2 / r.0).clamp(0.457, 0.485),
            0.1 * MM,
        ),
        format!("flat length as a fraction of the roller size, {NHBB}"),
    );
    let crown_drop = estimated(
        round_to(nhbb(size_mm, |r| r.1) * MM, 0.001 * MM),
        format!("crown drop interpolated in D_w, {NHBB}"),
    );
    let roller_chamfer = estimated(
        round_to(nhbb(size_mm, |r| r.3) * MM, 0.05 * MM),
        format!("corner interpolated in D_w, {NHBB}"),
    );
    let oil_temperature = input.operating.map(|op| match op.oil_temperature {
        Some(t) => source(t, "given (--oil-temperature)"),
        None => Dim {
            value: ASSUMED_OIL_TEMPERATURE_C + 273.15,
            basis: Basis::Estimated(format!(
                "ASSUMED {ASSUMED_OIL_TEMPERATURE_C} °C, rolldyn new's stand-in for a missing \
                 --oil-temperature: set your oil temperature"
            )),
        },
    });
    let mut warnings = Vec::new();
    if oil_temperature
        .as_ref()
        .is_some_and(|t| matches!(t.basis, Basis::Estimated(_)))
    {
        warnings.push(format!(
            "no --oil-temperature: the model's operating.temperatures.oil is the assumed \
             {ASSUMED_OIL_TEMPERATURE_C} °C (marked ASSUMED in the file)"
        ));
    }
    if input.oil.is_none() {
        warnings.push(format!(
            "no --oil: the model's lubricant is the assumed {} (marked ASSUMED in the file)",
            crate::ASSUMED_OIL
        ));
    }
    Ok(BearingDesign {
        input: input.clone(),
        chamfer_min,
        roller_diameter: dw,
        roller_length: lw,
        roller_count,
        roller_count_basis,
        pitch_diameter: pitch,
        clearance: Dim {
            value: g_r,
            basis: Basis::Source(format!(
                "ISO 5753-1 Table 4, group {} {}–{} µm for d = {} mm: mid value",
                input.clearance_group.name(),
                clearance_range[0],
                clearance_range[1],
                b.bore / MM
            )),
        },
        inner_raceway,
        outer_raceway,
        guiding_rib,
        other_rib,
        rib_play,
        rib_spacing,
        land_width,
        floating_clearance,
        cage_bore,
        cage_outside,
        cage_width,
        pocket_axial,
        face_clearance,
        lip,
        no_lip,
        fillet_radius,
        edge_break: estimated(0.3 * MM, "edge break 0.3 mm as the example models"),
        crown_straight,
        crown_drop,
        roller_chamfer,
        raceway_ra: source(
            RACEWAY_RA_UM * 1e-6,
            format!("{NHBB}: roller paths 6 µin Ra"),
        ),
        roller_ra: estimated(
            RACEWAY_RA_UM * 1e-6,
            "as the raceways (NHBB gives no roller finish)",
        ),
        cage_ra: estimated(1.6e-6, "machined surface Ra 1.6 µm, theory §14.4"),
        oil_temperature,
        warnings,
    })
}

fn check_boundary(b: &crate::Boundary) -> Result<(), DesignError> {
    let positive = |v: f64| v.is_finite() && v > 0.0;
    if !positive(b.bore) {
        return Err(DesignError::new("--bore", "must be a positive length"));
    }
    if !(positive(b.outside) && b.outside > b.bore) {
        return Err(DesignError::new(
            "--outside",
            "must be larger than the bore",
        ));
    }
    if !(positive(b.width) && b.width <= b.outside) {
        return Err(DesignError::new(
            "--width",
            "must be positive and at most the outside diameter",
        ));
    }
    Ok(())
}

fn roller_diameter(input: &DesignInput) -> Result<Dim, DesignError> {
    let b = &input.boundary;
    if let Some(d) = input.roller_diameter {
        if !(d > 0.0 && d < 0.5 * (b.outside - b.bore)) {
            return Err(DesignError::new(
                "--roller-diameter",
                format!(
                    "{} does not fit the section height (D − d)/2 = {}",
                    mm(d),
                    mm(0.5 * (b.outside - b.bore))
                ),
            ));
        }
        return Ok(source(d, "given (--roller-diameter)"));
    }
    let raw = ROLLER_DIAMETER_FRACTION * (b.outside - b.bore);
    let step = if raw < 10.0 * MM { 0.5 * MM } else { 1.0 * MM };
    Ok(estimated(
        round_to(raw, step),
        format!(
            "D_w ≈ {} (D − d) = {}, rounded to {}: the middle of the rule of thumb \
             0.25–0.3 (D − d), theory §14.2",
            ROLLER_DIAMETER_FRACTION,
            mm(raw),
            mm(step)
        ),
    ))
}

fn roller_length(input: &DesignInput, rib_width: f64, d_w: f64) -> Result<Dim, DesignError> {
    let width = input.boundary.width;
    if let Some(l) = input.roller_length {
        if !(l > 0.0 && l < width) {
            return Err(DesignError::new(
                "--roller-length",
                format!(
                    "{} must be positive and shorter than the width {}",
                    mm(l),
                    mm(width)
                ),
            ));
        }
        return Ok(source(l, "given (--roller-length)"));
    }
    let l = floor_to(width - 2.0 * rib_width, 0.5 * MM);
    if !(l > 0.5 * d_w) {
        return Err(DesignError::new(
            "--width",
            format!(
                "{} leaves no room for a roller between two ribs of {} (give --roller-length)",
                mm(width),
                mm(rib_width)
            ),
        ));
    }
    Ok(estimated(
        l,
        format!(
            "L_w = B − 2 (r_s + {} D_w) rounded down to 0.5 mm: two ribs of chamfer plus face, theory §14.2",
            RIB_FACE_PER_ROLLER_DIAMETER
        ),
    ))
}

fn radial_clearance(input: &DesignInput) -> Result<(Dim, [f64; 2]), DesignError> {
    let bore_mm = input.boundary.bore / MM;
    let range = iso5753::radial_clearance_um(input.clearance_group, bore_mm).ok_or_else(|| {
        DesignError::new(
            "--bore",
            format!(
                "{bore_mm} mm is beyond the clearance table (ISO 5753-1 Table 4 as tabulated \
                 here: d up to {} mm)",
                iso5753::BORE_RANGE_MM[1]
            ),
        )
    })?;
    let mid = 0.5 * (range[0] + range[1]) * 1e-6;
    Ok((derived(mid, ""), range))
}

fn check_walls(
    b: &crate::Boundary,
    inner_raceway: f64,
    outer_raceway: f64,
    input: &DesignInput,
) -> Result<(), DesignError> {
    let input_name = if input.roller_diameter.is_some() {
        "--roller-diameter"
    } else {
        "--outside"
    };
    let (inner_wall, outer_wall) = (
        0.5 * (inner_raceway - b.bore),
        0.5 * (b.outside - outer_raceway),
    );
    let min_wall = 0.1 * (outer_raceway - inner_raceway);
    if inner_wall < min_wall || outer_wall < min_wall {
        return Err(DesignError::new(
            input_name,
            format!(
                "the rings' walls under the raceways ({} inner, {} outer) are thinner than 0.1 \
                 of the roller space",
                mm(inner_wall),
                mm(outer_wall)
            ),
        ));
    }
    Ok(())
}

fn roller_count(
    input: &DesignInput,
    pitch: f64,
    d_w: f64,
    face_clearance: f64,
) -> Result<(usize, Basis), DesignError> {
    if let Some(z) = input.rollers {
        if z < 3 {
            return Err(DesignError::new(
                "--rollers",
                "a bearing needs at least 3 rollers",
            ));
        }
        return Ok((z, Basis::Source("given (--rollers)".into())));
    }
    let pocket_pitch = d_w + face_clearance + BAR_PER_ROLLER_DIAMETER * d_w;
    let z = (PI * pitch / pocket_pitch).floor() as usize;
    Ok((
        z,
        Basis::Estimated(format!(
            "Z = ⌊π D_pw / (D_w + face clearance + {} D_w)⌋: cage bars at least {} D_w wide on \
             the pitch circle, theory §14.2",
            BAR_PER_ROLLER_DIAMETER, BAR_PER_ROLLER_DIAMETER
        )),
    ))
}

/// The retaining lip: at the bore of an outer-ring guided cage (the rollers stay in the cage
/// when the inner ring is withdrawn), at the outside of an inner-ring guided one. Its edges are
/// `play` from a centred roller and `LIP_WINDOW_PER_ROLLER_DIAMETER` D_w apart; none where the
/// cage wall leaves the lip thinner than `LIP_MIN_THICKNESS_PER_ROLLER_DIAMETER` D_w.
fn retaining_lip(
    at_bore: bool,
    pitch_radius: f64,
    roller_radius: f64,
    play: f64,
    cage_inner_radius: f64,
    cage_outer_radius: f64,
) -> (Option<Lip>, Option<String>) {
    let half_window = LIP_WINDOW_PER_ROLLER_DIAMETER * roller_radius;
    let offset = ((roller_radius + play).powi(2) - half_window.powi(2)).sqrt();
    let (rho, thickness) = if at_bore {
        let rho = pitch_radius - offset;
        (rho, rho - cage_inner_radius)
    } else {
        let rho = pitch_radius + offset;
        (rho, cage_outer_radius - rho)
    };
    let min_thickness = LIP_MIN_THICKNESS_PER_ROLLER_DIAMETER * 2.0 * roller_radius;
    if thickness < min_thickness {
        return (
            None,
            Some(format!(
                "no retaining lip: the cage wall leaves {} for it, less than {} D_w; the pocket \
                 does not hold the rollers when the ring is withdrawn",
                mm(thickness.max(0.0)),
                LIP_MIN_THICKNESS_PER_ROLLER_DIAMETER
            )),
        );
    }
    let diameter = 2.0 * rho.hypot(half_window);
    let rule = format!(
        "edges {} from a centred roller (1.2 × land gap + G_r/2), window {} D_w, theory §14.4",
        mm(play),
        LIP_WINDOW_PER_ROLLER_DIAMETER
    );
    (
        Some(Lip {
            at_bore,
            diameter: estimated(round_to(diameter, 0.001 * MM), rule.clone()),
            window: estimated(round_to(2.0 * half_window, 0.001 * MM), rule),
            tip_radius: estimated(
                (0.2 * MM).min(round_to(0.25 * thickness, 0.01 * MM)),
                "lip edge radius 0.2 mm as 2002834, at most a quarter of the lip",
            ),
        }),
        None,
    )
}
