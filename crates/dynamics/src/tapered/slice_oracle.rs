//! The test oracle of the tapered raceway slices: the scalar path that evaluated the traction of
//! each slice with its own call of [`traction`] (main before issue 40 item 3), kept to check
//! the batched path of [`super::rhs`] against it (`batched_slices_match_the_scalar_oracle`).

use super::contacts::RollerContacts;
use super::model::TaperedModel;
use super::rhs::{CUP, RollerReport, body_velocity, contact_normal, half_plane, line_curvature};
use crate::ends::BodyKin;
use crate::kinematics::RollerKinematics;
use crate::rhs::Wrench;
use crate::vec3::{V3, add, axpy, cross, dot, norm, perp, power, scale, sub};
use rolldyn_lubrication::{ContactGeometry, ContactState, traction};

/// The slices of one roller on the cone (`race = 0`) and the cup (`race = 1`), one traction
/// call per slice.
#[allow(clippy::too_many_arguments)]
pub(super) fn raceways(
    model: &TaperedModel,
    row: usize,
    rk: &RollerKinematics,
    inner: &BodyKin,
    roller: &mut Wrench,
    f_inner: &mut V3,
    (report, mut record): (&mut RollerReport, Option<&mut RollerContacts>),
) {
    let geo = &model.rows[row];
    let u = scale(rk.a, geo.sigma);
    let s = &model.slices;
    let temps = &model.conditions.temperatures;
    for (race, (body, line)) in [(inner, &geo.cone), (&CUP, &geo.cup)]
        .into_iter()
        .enumerate()
    {
        let (mut total, mut sliding) = (0.0, 0.0);
        let mut slices = record.as_deref_mut().map(|r| {
            let c = if race == 0 { &mut r.cone } else { &mut r.cup };
            c.clear();
            c
        });
        for i in 0..s.x.len() {
            let centre = axpy(rk.c, s.x[i], u);
            let (rho, zeta, e_rho) = half_plane(body, centre);
            let delta = s.reach[race][i] - line.distance(rho, zeta);
            if delta <= 0.0 {
                continue;
            }
            let n = contact_normal(line, e_rho, body.axis);
            let p = axpy(centre, -s.reach[race][i], n);
            let v_roll = add(rk.v, cross(rk.w, sub(p, rk.c)));
            let v_ring = body_velocity(body, p);
            let v_rel = sub(v_roll, v_ring);
            let elastic = s.k[race][i] * power(delta, s.n[race]);
            let q = s.damping[race][i].normal_force(elastic, delta, -dot(v_rel, n));
            if q <= 0.0 {
                continue;
            }
            let vt = perp(v_rel, n);
            let vs = norm(vt);
            let frame = [0.0, 0.0, rk.orbit];
            let mean = scale(
                add(sub(v_roll, cross(frame, p)), sub(v_ring, cross(frame, p))),
                0.5,
            );
            let u_roll = norm(perp(mean, n));
            let ring_curvature = line_curvature(model, race, rho);
            let reduced_radius = 1.0 / (model.half_angle.cos() / s.radius[i] + ring_curvature);
            let state = ContactState {
                normal_force_n: q,
                geometry: ContactGeometry::Line {
                    length_m: s.length[i],
                },
                reduced_radius_m: reduced_radius,
                reduced_modulus_pa: model.reduced_modulus,
                rolling_speed_m_s: u_roll,
                sliding_speed_m_s: vs,
                temperature_k: if race == 0 {
                    temps.inner_raceway_k
                } else {
                    temps.outer_raceway_k
                },
                roughness_ra_m: model.roughness,
                film_thickness_m: None,
            };
            let tr = traction(&state, &model.traction);
            let mu = tr.coefficient.abs();
            if let Some(c) = slices.as_deref_mut() {
                c.force_n[i] = q;
                c.sliding_m_s[i] = vs;
                c.lambda[i] = tr.lambda;
                c.half_width_m[i] = tr.half_width_m;
                c.reduced_radius_m[i] = reduced_radius;
                c.ring_radius_m[i] = rho;
            }
            let mut f = scale(n, q);
            if vs > 0.0 {
                f = axpy(f, -mu * q / vs, vt);
            }
            roller.force = add(roller.force, f);
            roller.moment = add(roller.moment, cross(sub(p, rk.c), f));
            if race == 0 {
                *f_inner = sub(*f_inner, f);
                report.cone_slice_max = report.cone_slice_max.max(q);
            }
            total += q;
            sliding += q * vs;
            report.slip = report.slip.max(vs / u_roll.max(1e-3));
        }
        let mean_sliding = if total > 0.0 { sliding / total } else { 0.0 };
        if race == 0 {
            (report.cone, report.cone_sliding) = (total, mean_sliding);
        } else {
            (report.cup, report.cup_sliding) = (total, mean_sliding);
        }
    }
}
