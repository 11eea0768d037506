//! Check: validates a model and derives its quantities — pitch diameter, clearances, mass
//! properties, the cage pocket as built, epicyclic speeds (docs/theory.md §1.6; the tapered
//! bearing's dimensions per "Double-row tapered bearing geometry").

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::table::Tables;
use rolldyn_geometry::{BearingModel, DoubleRowTaperedBearing, MassProperties};
use rolldyn_units::{AngularSpeed, Quantity};
use serde::{Deserialize, Serialize};
use std::fmt;

/// Inner-ring speed when neither the request nor the model gives one, rad/s (1000 rpm).
const FALLBACK_SPEED: f64 = 1000.0 * std::f64::consts::PI / 30.0;

/// A check: the speeds at which the epicyclic speeds are given.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct CheckRequest {
    /// Inner-ring speed (default: the model's `operating.inner_speed`, else 1000 rpm).
    pub speed: Option<Quantity<AngularSpeed>>,
    /// Outer-ring speed, intershaft bearings (default: the model's `operating.outer_speed`,
    /// else 0).
    pub outer_speed: Option<Quantity<AngularSpeed>>,
}

/// Mass properties.
#[derive(Clone, Debug, Serialize)]
pub struct Mass {
    pub mass_kg: f64,
    pub axial_inertia_kg_m2: f64,
    pub transverse_inertia_kg_m2: f64,
}

impl From<MassProperties> for Mass {
    fn from(m: MassProperties) -> Self {
        Self {
            mass_kg: m.mass,
            axial_inertia_kg_m2: m.axial_inertia,
            transverse_inertia_kg_m2: m.transverse_inertia,
        }
    }
}

/// A retaining lip as built.
#[derive(Clone, Debug, Serialize)]
pub struct LipSummary {
    pub diameter_m: f64,
    pub window_m: f64,
    pub tip_radius_m: f64,
}

/// The cage pocket as `rolldyn check` reports it (SI units, docs/theory.md §1.6).
#[derive(Clone, Debug, Serialize)]
pub struct PocketSummary {
    pub faces: &'static str,
    pub face_clearance_m: f64,
    /// pocket width between the faces at the pitch circle
    pub face_width_m: f64,
    pub outer_lip: Option<LipSummary>,
    pub inner_lip: Option<LipSummary>,
    pub axial_m: f64,
    pub fillet_radius_m: f64,
    /// circumferential travel of a centred roller to a wall, the piece it meets and where
    pub circumferential_play_per_side_m: f64,
    pub circumferential_stop: &'static str,
    pub circumferential_contact_diameter_m: f64,
    /// radial travel of the roller to a lip (null: no lip stops it)
    pub radial_play_outward_m: Option<f64>,
    pub radial_play_inward_m: Option<f64>,
    pub closing_displacement_m: f64,
    /// the roller at the pitch radius ± half the radial clearance fits its pocket
    pub fits: bool,
    pub bar_width_min_m: f64,
    pub bar_width_min_diameter_m: f64,
    pub bar_width_bore_m: f64,
    pub bar_width_outside_m: f64,
    pub bar_area_m2: f64,
    pub bar_second_moment_m4: f64,
}

impl PocketSummary {
    /// The pocket of `b`'s cage (none without a cage or when its play cannot be found).
    pub fn of(b: &rolldyn_geometry::CylindricalRollerBearing) -> Option<Self> {
        let cage = b.cage.as_ref()?;
        let p = &cage.pocket;
        let ctx = b.pocket_context(cage);
        let play = p.play(&ctx).ok()?;
        let section = p.bar_section(&ctx).ok()?;
        let lip = |l: Option<rolldyn_geometry::RetainingLip>| {
            l.map(|l| LipSummary {
                diameter_m: l.diameter,
                window_m: l.window,
                tip_radius_m: l.tip_radius,
            })
        };
        Some(Self {
            faces: match p.faces {
                rolldyn_geometry::PocketFaces::Flat => "flat",
                rolldyn_geometry::PocketFaces::Concave => "concave",
            },
            face_clearance_m: p.face_clearance,
            face_width_m: b.roller.diameter + p.face_clearance,
            outer_lip: lip(p.outer_lip),
            inner_lip: lip(p.inner_lip),
            axial_m: p.axial,
            fillet_radius_m: p.fillet_radius,
            circumferential_play_per_side_m: play.circumferential_per_side,
            circumferential_stop: play.circumferential_stop.name(),
            circumferential_contact_diameter_m: play.circumferential_contact_diameter,
            radial_play_outward_m: play.radial_outward,
            radial_play_inward_m: play.radial_inward,
            closing_displacement_m: play.closing_displacement,
            fits: p.check_fit(&ctx, 0.5 * b.clearance.radial.max(0.0)).is_ok(),
            bar_width_min_m: section.width_min,
            bar_width_min_diameter_m: 2.0 * section.radius_of_min,
            bar_width_bore_m: section.width_inner,
            bar_width_outside_m: section.width_outer,
            bar_area_m2: section.area,
            bar_second_moment_m4: section.second_moment,
        })
    }
}

/// Derived quantities of a model (SI units).
#[derive(Clone, Debug, Default, Serialize)]
pub struct Summary {
    pub name: String,
    pub kind: &'static str,
    pub roller_diameter_m: f64,
    pub roller_length_m: f64,
    pub effective_contact_length_m: f64,
    pub crown_radius_m: Option<f64>,
    pub slices: usize,
    pub roller: Option<Mass>,
    pub roller_count: Option<usize>,
    pub pitch_diameter_m: Option<f64>,
    pub geometric_clearance_m: Option<f64>,
    pub radial_clearance_m: Option<f64>,
    pub roller_rib_axial_clearance_m: Option<f64>,
    pub misalignment_rad: f64,
    pub inner_ring: Option<Mass>,
    pub outer_ring: Option<Mass>,
    pub cage: Option<Mass>,
    pub cage_land_diameter_m: Option<f64>,
    /// the pocket profile, its plays, the fit check and the bar section
    pub cage_pocket: Option<PocketSummary>,
    /// circumferential play of a centred roller on each side of its pocket
    pub cage_pocket_play_per_side_m: Option<f64>,
    /// smallest cage displacement that closes a pocket on its roller
    pub cage_pocket_closing_displacement_m: Option<f64>,
    /// half the floating clearance
    pub cage_land_radial_gap_m: Option<f64>,
    /// the land stops the cage before a pocket closes
    pub cage_land_guided: Option<bool>,
    pub inner_speed_rad_s: Option<f64>,
    pub outer_speed_rad_s: Option<f64>,
    pub epicyclic_cage_speed_rad_s: Option<f64>,
    pub epicyclic_roller_speed_rad_s: Option<f64>,
    /// findings a designer should look at (the model runs as given)
    pub design_notes: Vec<Note>,
}

/// A design note on a model key (`rolldyn_geometry::DesignNote`).
#[derive(Clone, Debug, Serialize)]
pub struct Note {
    pub key: String,
    pub text: String,
}

/// Derived dimensions of a double-row tapered bearing (SI units; docs/theory.md "Double-row
/// tapered bearing geometry").
#[derive(Clone, Debug, Serialize)]
pub struct TaperedSummary {
    pub name: String,
    pub kind: &'static str,
    pub misalignment_rad: f64,
    pub arrangement: &'static str,
    pub rollers_per_row: usize,
    pub pitch_diameter_m: f64,
    pub roller_mean_diameter_m: f64,
    pub roller_large_diameter_m: f64,
    pub roller_small_diameter_m: f64,
    pub roller_length_m: f64,
    pub roller_half_angle_rad: f64,
    pub roller_axis_angle_rad: f64,
    pub cone_angle_rad: f64,
    pub cup_angle_rad: f64,
    pub apex_distance_m: f64,
    pub apex_mismatch_m: f64,
    /// cone and cup contact diameters in the roller mid-length section
    pub cone_contact_diameter_m: f64,
    pub cup_contact_diameter_m: f64,
    pub row_spacing_m: f64,
    pub axial_clearance_m: f64,
    pub normal_gap_per_row_m: f64,
    pub large_rib_height_m: f64,
    pub large_rib_undercut_m: f64,
    pub large_rib_contact_height_m: f64,
    /// initial end–rib contact of row 2 (z > 0), bearing coordinates
    pub large_rib_contact_r_m: f64,
    pub large_rib_contact_z_m: f64,
    /// angle of the contact on the end sphere from the roller axis
    pub large_rib_contact_angle_rad: f64,
    /// axial distance from the roller mid-point to where the rib face meets the raceway line
    pub large_rib_face_base_from_roller_mid_m: f64,
    /// axial section (seed 000 §3.2.2)
    pub end_rib_reduced_curvature_per_m: f64,
    /// along the circumference, with the rib face's Meusnier curvature (theory §12.1)
    pub end_rib_circumferential_reduced_curvature_per_m: f64,
    pub small_rib_gap_m: f64,
    pub slices: usize,
    pub roller: Mass,
    /// roller centre of mass from mid-length, + toward the large end
    pub roller_centre_of_mass_offset_m: f64,
    pub cage: Mass,
    pub cage_pocket_clearance_m: f64,
    pub inner_speed_rad_s: f64,
    pub epicyclic_cage_speed_rad_s: f64,
    pub outer_roller_pass_frequency_hz: f64,
    pub inner_roller_pass_frequency_hz: f64,
}

impl TaperedSummary {
    /// The dimensions of `b`, its speeds at `inner_speed` (rad/s, cup fixed).
    pub fn of(b: &DoubleRowTaperedBearing, inner_speed: f64) -> Self {
        let row = b.row(1);
        let rib = row.large_rib;
        let (cone_r, cup_r) = b.contact_radii();
        let (outer_pass, inner_pass) = b.pass_frequencies(inner_speed);
        let r = &b.roller;
        Self {
            name: b.name.clone(),
            kind: "double-row tapered",
            misalignment_rad: b.misalignment.inner_ring_tilt,
            arrangement: match b.arrangement {
                rolldyn_geometry::Arrangement::O => "O (back-to-back)",
                rolldyn_geometry::Arrangement::X => "X (face-to-face)",
            },
            rollers_per_row: b.rollers_per_row,
            pitch_diameter_m: b.pitch_diameter,
            roller_mean_diameter_m: r.mean_diameter,
            roller_large_diameter_m: r.large_diameter(),
            roller_small_diameter_m: r.small_diameter(),
            roller_length_m: r.length,
            roller_half_angle_rad: r.half_angle,
            roller_axis_angle_rad: b.roller_axis_angle(),
            cone_angle_rad: b.cone_angle(),
            cup_angle_rad: b.cup_angle(),
            apex_distance_m: b.apex_distance(),
            apex_mismatch_m: b.apex_mismatch(),
            cone_contact_diameter_m: 2.0 * cone_r,
            cup_contact_diameter_m: 2.0 * cup_r,
            row_spacing_m: b.row_spacing,
            axial_clearance_m: b.axial_clearance,
            normal_gap_per_row_m: b.normal_gap(),
            large_rib_height_m: b.large_rib.height,
            large_rib_undercut_m: b.large_rib.undercut,
            large_rib_contact_height_m: b.large_rib.contact_height(),
            large_rib_contact_r_m: rib.point.r,
            large_rib_contact_z_m: rib.point.z,
            large_rib_contact_angle_rad: rib.normal.dot(-row.roller_axis).clamp(-1.0, 1.0).acos(),
            large_rib_face_base_from_roller_mid_m: (rib.face_base.z - row.roller_mid.z).abs(),
            end_rib_reduced_curvature_per_m: 1.0 / r.large_end_sphere_radius
                - b.large_rib.face.curvature(),
            end_rib_circumferential_reduced_curvature_per_m: 1.0 / r.large_end_sphere_radius
                + rib.circumferential_curvature(),
            small_rib_gap_m: b.small_rib_gap,
            slices: r.slice_count,
            roller: r.mass_properties().into(),
            roller_centre_of_mass_offset_m: r.centre_of_mass_offset(),
            cage: MassProperties {
                mass: b.cage.mass,
                axial_inertia: b.cage.inertia_axial,
                transverse_inertia: b.cage.inertia_transverse,
            }
            .into(),
            cage_pocket_clearance_m: b.cage.pocket_clearance,
            inner_speed_rad_s: inner_speed,
            epicyclic_cage_speed_rad_s: b.epicyclic_cage_speed(inner_speed),
            outer_roller_pass_frequency_hz: outer_pass,
            inner_roller_pass_frequency_hz: inner_pass,
        }
    }
}

/// The derived quantities of `model` at the ring speeds `inner_speed`, `outer_speed` (rad/s).
pub fn summarise(model: &BearingModel, inner_speed: f64, outer_speed: f64) -> Summary {
    let mut s = Summary {
        name: model.name().to_string(),
        misalignment_rad: model.misalignment().inner_ring_tilt,
        ..Summary::default()
    };
    if let Some(roller) = model.roller() {
        s.roller_diameter_m = roller.diameter;
        s.roller_length_m = roller.length;
        s.effective_contact_length_m = roller.profile.effective_length();
        s.crown_radius_m = roller.profile.crown_radius();
        s.slices = roller.slice_count;
        s.roller = Some(roller.mass_properties.into());
    }
    match model {
        BearingModel::RollerRaceway(p) => {
            s.kind = "roller-raceway";
            let ring = Some(p.raceway.mass_properties.into());
            if p.raceway_is_inner {
                s.inner_ring = ring;
            } else {
                s.outer_ring = ring;
            }
        }
        BearingModel::Cylindrical(b) => {
            s.kind = "cylindrical";
            s.roller_count = Some(b.roller_count);
            s.pitch_diameter_m = Some(b.pitch_diameter());
            s.geometric_clearance_m = Some(b.geometric_clearance());
            s.radial_clearance_m = Some(b.clearance.radial);
            s.roller_rib_axial_clearance_m = b.roller_rib_axial_clearance();
            s.inner_ring = Some(b.inner_ring.mass_properties.into());
            s.outer_ring = Some(b.outer_ring.mass_properties.into());
            s.cage = b.cage.as_ref().map(|c| c.mass_properties.into());
            s.cage_land_diameter_m = b.cage.as_ref().and_then(|c| c.land_diameter());
            s.cage_pocket = PocketSummary::of(b);
            if let Some(g) = b.cage_guidance_check() {
                s.cage_pocket_play_per_side_m = Some(g.play.circumferential_per_side);
                s.cage_pocket_closing_displacement_m = Some(g.play.closing_displacement);
                s.cage_land_radial_gap_m = Some(g.land_radial_gap);
                s.cage_land_guided = Some(g.land_guided());
            }
            s.inner_speed_rad_s = Some(inner_speed);
            s.outer_speed_rad_s = Some(outer_speed);
            s.epicyclic_cage_speed_rad_s = Some(b.epicyclic_cage_speed(inner_speed, outer_speed));
            s.epicyclic_roller_speed_rad_s =
                Some(b.epicyclic_roller_speed(inner_speed, outer_speed));
            s.design_notes = b
                .design_notes()
                .into_iter()
                .map(|n| Note {
                    key: n.key,
                    text: n.text,
                })
                .collect();
        }
        BearingModel::Tapered(_) => s.kind = "double-row tapered",
    }
    s
}

/// A length in mm.
fn mm(v: f64) -> String {
    format!("{:.4} mm", v * 1e3)
}

/// Mass properties in kg and kg·m².
fn mass(m: &Mass) -> String {
    format!(
        "{:.4} kg, J_axial {:.4e} kg·m², J_transverse {:.4e} kg·m²",
        m.mass_kg, m.axial_inertia_kg_m2, m.transverse_inertia_kg_m2
    )
}

/// An angular speed in rad/s and rpm.
fn rpm(w: f64) -> String {
    format!(
        "{:.2} rad/s ({:.1} rpm)",
        w,
        w * 30.0 / std::f64::consts::PI
    )
}

/// An angle in degrees and arc-minutes.
fn angle(a: f64) -> String {
    format!("{:.4}° ({:.2}′)", a.to_degrees(), a.to_degrees() * 60.0)
}

/// Human-readable lines of a summary (mm, kg, rpm).
fn describe(s: &Summary) -> Vec<String> {
    let mut out = vec![format!("model {} ({}) — valid", s.name, s.kind)];
    let mut line = |label: &str, value: String| out.push(format!("  {label:<34} {value}"));
    line(
        "roller diameter × length",
        format!("{} × {}", mm(s.roller_diameter_m), mm(s.roller_length_m)),
    );
    line("effective contact length", mm(s.effective_contact_length_m));
    if let Some(r) = s.crown_radius_m {
        line("crown radius (derived if not given)", mm(r));
    }
    line("slices per roller", s.slices.to_string());
    if let Some(m) = &s.roller {
        line("roller mass properties", mass(m));
    }
    if let Some(z) = s.roller_count {
        line("rollers", z.to_string());
    }
    if let Some(d) = s.pitch_diameter_m {
        line("pitch diameter d_m", mm(d));
    }
    if let Some(g) = s.geometric_clearance_m {
        line("clearance from raceway diameters", mm(g));
    }
    if let Some(g) = s.radial_clearance_m {
        line("radial clearance (used)", mm(g));
    }
    if let Some(a) = s.roller_rib_axial_clearance_m {
        line("roller–rib axial clearance", mm(a));
    }
    line(
        "misalignment",
        format!("{:.2}′", s.misalignment_rad.to_degrees() * 60.0),
    );
    for (label, m) in [
        ("inner ring", &s.inner_ring),
        ("outer ring", &s.outer_ring),
        ("cage", &s.cage),
    ] {
        if let Some(m) = m {
            line(&format!("{label} mass properties"), mass(m));
        }
    }
    if let Some(d) = s.cage_land_diameter_m {
        line("cage guiding land diameter", mm(d));
    }
    if let Some(p) = &s.cage_pocket {
        line(
            "cage pocket faces",
            format!(
                "{}, {} apart at the pitch circle (clearance {})",
                p.faces,
                mm(p.face_width_m),
                mm(p.face_clearance_m)
            ),
        );
        for (label, lip) in [("outer lip", &p.outer_lip), ("inner lip", &p.inner_lip)] {
            if let Some(l) = lip {
                line(
                    &format!("cage pocket {label}"),
                    format!(
                        "Ø{}, window {}, tip radius {}",
                        mm(l.diameter_m),
                        mm(l.window_m),
                        mm(l.tip_radius_m)
                    ),
                );
            }
        }
        line(
            "roller play in its pocket",
            format!(
                "{} per side to the {} at Ø{}; radially {} out / {} in",
                mm(p.circumferential_play_per_side_m),
                p.circumferential_stop,
                mm(p.circumferential_contact_diameter_m),
                p.radial_play_outward_m.map_or("free".into(), mm),
                p.radial_play_inward_m.map_or("free".into(), mm),
            ),
        );
        line(
            "pocket fit",
            if p.fits {
                "the roller fits its pocket at the pitch radius ± half the radial clearance".into()
            } else {
                "the pocket cuts the roller".into()
            },
        );
        line(
            "cage bar section",
            format!(
                "width {} (narrowest, at Ø{}), {} at the bore, {} outside; area {:.2} mm², I {:.1} mm⁴",
                mm(p.bar_width_min_m),
                mm(p.bar_width_min_diameter_m),
                mm(p.bar_width_bore_m),
                mm(p.bar_width_outside_m),
                p.bar_area_m2 * 1e6,
                p.bar_second_moment_m4 * 1e12
            ),
        );
    }
    if let (Some(play), Some(closing), Some(gap), Some(guided)) = (
        s.cage_pocket_play_per_side_m,
        s.cage_pocket_closing_displacement_m,
        s.cage_land_radial_gap_m,
        s.cage_land_guided,
    ) {
        line("pocket play per side", mm(play));
        line(
            "cage travel: pockets close / land",
            format!("{} / {}", mm(closing), mm(gap)),
        );
        line(
            "what centres the cage",
            if guided {
                "the land (it stops the cage before a pocket closes)".into()
            } else {
                "the rollers: a pocket closes before the land gap (see docs/theory.md §1.6)".into()
            },
        );
    }
    if let (Some(wi), Some(wo), Some(wc), Some(wr)) = (
        s.inner_speed_rad_s,
        s.outer_speed_rad_s,
        s.epicyclic_cage_speed_rad_s,
        s.epicyclic_roller_speed_rad_s,
    ) {
        line(
            "inner / outer ring speed",
            format!("{} / {}", rpm(wi), rpm(wo)),
        );
        line("epicyclic cage speed", rpm(wc));
        line("epicyclic roller spin speed", rpm(wr));
    }
    for note in &s.design_notes {
        out.push(format!("  note ({}): {}", note.key, note.text));
    }
    out
}

/// Human-readable lines of a tapered summary (mm, degrees and arc-minutes, kg, rpm, Hz).
fn describe_tapered(t: &TaperedSummary) -> Vec<String> {
    let mut out = vec![format!("model {} ({}) — valid", t.name, t.kind)];
    let mut line = |label: &str, value: String| out.push(format!("  {label:<40} {value}"));
    line("arrangement", t.arrangement.to_string());
    line("rollers per row", t.rollers_per_row.to_string());
    line(
        "roller D_w (mean) / large / small",
        format!(
            "{} / {} / {}",
            mm(t.roller_mean_diameter_m),
            mm(t.roller_large_diameter_m),
            mm(t.roller_small_diameter_m)
        ),
    );
    line("roller length", mm(t.roller_length_m));
    line("roller half-angle β", angle(t.roller_half_angle_rad));
    line(
        "roller-axis angle θ_r (apex condition)",
        angle(t.roller_axis_angle_rad),
    );
    line("cone angle α_i = θ_r − β", angle(t.cone_angle_rad));
    line(
        "cup angle α_o = θ_r + β (contact angle)",
        angle(t.cup_angle_rad),
    );
    line("roller mid-point → apex", mm(t.apex_distance_m));
    line(
        "apex mismatch",
        format!("{:.3e} mm", t.apex_mismatch_m * 1e3),
    );
    line("pitch diameter d_m", mm(t.pitch_diameter_m));
    line(
        "cone / cup contact Ø (mid-length)",
        format!(
            "{} / {}",
            mm(t.cone_contact_diameter_m),
            mm(t.cup_contact_diameter_m)
        ),
    );
    line("row spacing (roller mid-points)", mm(t.row_spacing_m));
    line("axial clearance", mm(t.axial_clearance_m));
    line(
        "normal gap per row ½ c_a sin α_o",
        mm(t.normal_gap_per_row_m),
    );
    line(
        "large rib height / undercut",
        format!(
            "{} / {}",
            mm(t.large_rib_height_m),
            mm(t.large_rib_undercut_m)
        ),
    );
    line(
        "end–rib contact: height, angle on sphere",
        format!(
            "{} above the raceway, {}",
            mm(t.large_rib_contact_height_m),
            angle(t.large_rib_contact_angle_rad)
        ),
    );
    line(
        "end–rib contact (row 2): r, z",
        format!(
            "{}, {}",
            mm(t.large_rib_contact_r_m),
            mm(t.large_rib_contact_z_m)
        ),
    );
    line(
        "rib foot from roller mid-point (axial)",
        mm(t.large_rib_face_base_from_roller_mid_m),
    );
    line(
        "end–rib reduced curvature",
        format!("{:.4} 1/m", t.end_rib_reduced_curvature_per_m),
    );
    line(
        "  along the circumference",
        format!(
            "{:.4} 1/m",
            t.end_rib_circumferential_reduced_curvature_per_m
        ),
    );
    line("small-rib gap", mm(t.small_rib_gap_m));
    line("slices per roller", t.slices.to_string());
    line("roller mass properties", mass(&t.roller));
    line(
        "roller centre of mass (from mid-length)",
        mm(t.roller_centre_of_mass_offset_m),
    );
    line("cage mass properties (one row)", mass(&t.cage));
    line("cage pocket clearance", mm(t.cage_pocket_clearance_m));
    line(
        "misalignment",
        format!("{:.2}′", t.misalignment_rad.to_degrees() * 60.0),
    );
    line("inner ring speed (cup fixed)", rpm(t.inner_speed_rad_s));
    line("epicyclic cage speed", rpm(t.epicyclic_cage_speed_rad_s));
    line(
        "roller-pass frequency outer / inner",
        format!(
            "{:.2} Hz / {:.2} Hz",
            t.outer_roller_pass_frequency_hz, t.inner_roller_pass_frequency_hz
        ),
    );
    out
}

impl fmt::Display for Summary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&describe(self).join("\n"))
    }
}

impl fmt::Display for TaperedSummary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&describe_tapered(self).join("\n"))
    }
}

/// The derived quantities of a cylindrical (or roller–raceway) model, or of a double-row
/// tapered one; serialised as the summary itself.
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum CheckResult {
    Cylindrical(Box<Summary>),
    Tapered(Box<TaperedSummary>),
}

impl Tables for CheckResult {}

impl fmt::Display for CheckResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Cylindrical(s) => s.fmt(f),
            Self::Tapered(t) => t.fmt(f),
        }
    }
}

/// The check analysis.
pub struct Check;

impl Analysis for Check {
    const NAME: &'static str = "check";
    type Request = CheckRequest;
    type Result = CheckResult;

    fn run(request: &CheckRequest, context: &Context<'_>) -> Result<CheckResult, Failure> {
        let model = context.model.load()?;
        let flags = rolldyn_setup::FlagValues {
            speed: request.speed.map(|q| q.si()),
            outer_speed: request.outer_speed.map(|q| q.si()),
            ..Default::default()
        };
        flags.check(&model)?;
        let inner = flags
            .speed
            .or(model.operating.inner_speed)
            .unwrap_or(FALLBACK_SPEED);
        let outer = flags
            .outer_speed
            .or(model.operating.outer_speed)
            .unwrap_or(0.0);
        Ok(match &model.bearing {
            BearingModel::Tapered(b) => {
                CheckResult::Tapered(Box::new(TaperedSummary::of(b, inner)))
            }
            bearing => CheckResult::Cylindrical(Box::new(summarise(bearing, inner, outer))),
        })
    }
}
