//! Traction of many line-contact slices in one call (struct of arrays).
//!
//! The dynamics evaluates the traction of every loaded slice of every roller at every
//! integrator stage — a few hundred slices per right-hand side. One call per slice spends most
//! of its time in `exp`/`ln` calls and in building and returning the full [`Traction`] record.
//! [`SliceBatch`] collects the slices of many prepared contacts (SPEC §3.3: one film per
//! roller–raceway contact, the traction per slice with its own pressure, half-width and sliding
//! speed) and evaluates only the coefficients, in one loop over contiguous arrays that the
//! compiler vectorises (with the branch-free [`rolldyn_numerics::fastmath`] functions).
//!
//! The physics is exactly that of [`TractionModel::traction_prepared`]: both call
//! `lubricated_coefficient`. Laws without a film (two-level, seed 001) fall
//! back to [`traction()`] per slice.
//!
//! [`Traction`]: super::Traction

use super::table::HotProps;
use super::{
    BoundaryFriction, ContactTraction, FrictionLaw, Hydrodynamic, LubricatedFriction, MixedLimits,
    MurakiContact, MurakiSettings, MurakiSlice, PreparedContact, Rheology, SmallShearRate,
    TractionConfig, TractionModel, lubricated_coefficient, traction,
};
use crate::contact_state::{ContactGeometry, ContactState, SlicePressure, line_stiffness};
use crate::film::{FilmFormula, rigid_piezoviscous_line_many};
use crate::lubricant::{Lubricant, SolidThermal};
use crate::viscosity::PiezoViscosity;

/// Handle of a contact added to a [`SliceBatch`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BatchContact(usize);

/// A contact of the batch: its prepared oil, film and Λ, and its geometry.
#[derive(Debug, Clone, Copy)]
struct Contact {
    /// `None` for laws without a film (two-level, seed 001)
    prepared: Option<PreparedContact>,
    reduced_radius_m: f64,
    reduced_modulus_pa: f64,
    temperature_k: f64,
    roughness_ra_m: [f64; 2],
}

/// Slices of many line contacts of one traction model, evaluated together by
/// [`SliceBatch::evaluate`]. Allocates only while growing: reuse one batch with
/// [`SliceBatch::clear`].
#[derive(Debug, Clone, Default)]
pub struct SliceBatch {
    contacts: Vec<Contact>,
    contact_of: Vec<usize>,
    /// runs of consecutive slices of one contact: (contact, first slice), in slice order
    contact_runs: Vec<(usize, usize)>,
    normal_force_n: Vec<f64>,
    length_m: Vec<f64>,
    rolling_speed_m_s: Vec<f64>,
    sliding_speed_m_s: Vec<f64>,
    coefficient: Vec<f64>,
    lanes: ContactLanes,
    films: PendingFilms,
}

impl SliceBatch {
    /// An empty batch with room for `slices` slices.
    pub fn with_capacity(slices: usize) -> Self {
        Self {
            contacts: Vec::with_capacity(slices),
            contact_of: Vec::with_capacity(slices),
            contact_runs: Vec::with_capacity(slices),
            normal_force_n: Vec::with_capacity(slices),
            length_m: Vec::with_capacity(slices),
            rolling_speed_m_s: Vec::with_capacity(slices),
            sliding_speed_m_s: Vec::with_capacity(slices),
            coefficient: Vec::with_capacity(slices),
            lanes: ContactLanes::default(),
            films: PendingFilms::default(),
        }
    }

    /// Removes every contact and slice (keeps the memory).
    pub fn clear(&mut self) {
        self.contacts.clear();
        self.contact_of.clear();
        self.contact_runs.clear();
        self.films.clear();
    }

    /// Adds a contact. `whole` describes the whole contact (total load over the loaded length,
    /// mean entrainment speed, temperature, R', E', roughness); its film and Λ are computed once
    /// for all its slices ([`TractionModel::prepare_contact`]). Rigid–piezoviscous line films
    /// are computed for all contacts together in [`SliceBatch::evaluate`].
    pub fn add_contact(&mut self, model: &TractionModel, whole: &ContactState) -> BatchContact {
        let index = self.contacts.len();
        if self.same_oil_as_last(whole) {
            // a copy of the last contact (one move), then its own geometry and film inputs
            self.contacts.push(self.contacts[index - 1]);
            let contact = &mut self.contacts[index];
            contact.reduced_radius_m = whole.reduced_radius_m;
            contact.reduced_modulus_pa = whole.reduced_modulus_pa;
            contact.roughness_ra_m = whole.roughness_ra_m;
            if let Some(prepared) = contact.prepared.as_mut() {
                prepared.film_central_m = f64::NAN;
                prepared.film_minimum_m = f64::NAN;
                prepared.lambda = f64::NAN;
                self.films.push(index, &prepared.props, whole);
            }
            return BatchContact(index);
        }
        let prepared = model
            .prepare_contact_deferred(whole)
            .map(|(prepared, deferred)| {
                if deferred {
                    self.films.push(index, &prepared.props, whole);
                }
                prepared
            });
        self.contacts.push(Contact {
            prepared,
            reduced_radius_m: whole.reduced_radius_m,
            reduced_modulus_pa: whole.reduced_modulus_pa,
            temperature_k: whole.temperature_k,
            roughness_ra_m: whole.roughness_ra_m,
        });
        BatchContact(index)
    }

    /// Whether the last contact's preparation holds for `whole` too (with its own film): a
    /// loaded line contact at the same temperature as that contact, whose film was deferred.
    /// The oil properties, the resolved formula and the warnings depend on nothing else, so the
    /// table look-up is done once per raceway instead of once per contact.
    fn same_oil_as_last(&self, whole: &ContactState) -> bool {
        let Some(prepared) = self.contacts.last().and_then(|last| {
            (last.temperature_k == whole.temperature_k)
                .then_some(last.prepared.as_ref())
                .flatten()
        }) else {
            return false;
        };
        matches!(
            prepared.formula,
            Some(FilmFormula::RigidPiezoviscousLine | FilmFormula::Auto)
        ) && whole.normal_force_n > 0.0
            && whole.geometry.is_line()
    }

    /// Adds a slice of `contact`: normal force (N), slice length (m), rolling and sliding speed
    /// (m/s; the coefficient takes the sign of the sliding speed). Returns its index.
    pub fn push(
        &mut self,
        contact: BatchContact,
        normal_force_n: f64,
        length_m: f64,
        rolling_speed_m_s: f64,
        sliding_speed_m_s: f64,
    ) -> usize {
        self.push_block(
            contact,
            &[normal_force_n],
            &[length_m],
            &[rolling_speed_m_s],
            &[sliding_speed_m_s],
        )
    }

    /// Adds a block of slices of `contact`, one per element of the arrays (normal force N,
    /// slice length m, rolling and sliding speed m/s, as in [`SliceBatch::push`]). Slots with
    /// `normal_force_n ≤ 0` (unloaded slices, padding) get a zero coefficient. Returns the index
    /// of the first.
    pub fn push_block(
        &mut self,
        contact: BatchContact,
        normal_force_n: &[f64],
        length_m: &[f64],
        rolling_speed_m_s: &[f64],
        sliding_speed_m_s: &[f64],
    ) -> usize {
        let first = self.len();
        let n = normal_force_n.len();
        let to = first..first + n;
        let columns = self.columns_mut(to.end);
        columns.normal_force_n[to.clone()].copy_from_slice(normal_force_n);
        columns.length_m[to.clone()].copy_from_slice(&length_m[..n]);
        columns.rolling_speed_m_s[to.clone()].copy_from_slice(&rolling_speed_m_s[..n]);
        columns.sliding_speed_m_s[to].copy_from_slice(&sliding_speed_m_s[..n]);
        self.claim(contact, n)
    }

    /// The slice columns for writing slices in place, each at least `room` long: index `i` is
    /// slice `i`. Indices from [`SliceBatch::len`] on are free; write the next slices there
    /// and add them with [`SliceBatch::claim`]. Saves a copy when the slices are produced in
    /// an array already (the dynamics' slot loop writes its results here directly).
    pub fn columns_mut(&mut self, room: usize) -> SliceColumnsMut<'_> {
        let columns = [
            &mut self.normal_force_n,
            &mut self.length_m,
            &mut self.rolling_speed_m_s,
            &mut self.sliding_speed_m_s,
        ];
        for column in columns {
            if column.len() < room {
                column.resize(room, 0.0);
            }
        }
        SliceColumnsMut {
            normal_force_n: &mut self.normal_force_n,
            length_m: &mut self.length_m,
            rolling_speed_m_s: &mut self.rolling_speed_m_s,
            sliding_speed_m_s: &mut self.sliding_speed_m_s,
        }
    }

    /// Adds the `n` slices written in place after the last one ([`SliceBatch::columns_mut`])
    /// as slices of `contact`. Returns the index of the first.
    ///
    /// # Panics
    /// If the columns are shorter than the batch would then be.
    pub fn claim(&mut self, contact: BatchContact, n: usize) -> usize {
        let first = self.len();
        assert!(
            first + n <= self.normal_force_n.len(),
            "SliceBatch::claim: {n} slices from {first} were not written (room {})",
            self.normal_force_n.len()
        );
        self.contact_of.resize(first + n, contact.0);
        if n > 0
            && self
                .contact_runs
                .last()
                .is_none_or(|&(c, _)| c != contact.0)
        {
            self.contact_runs.push((contact.0, first));
        }
        first
    }

    /// Normal forces (N) and, after [`SliceBatch::evaluate`], traction coefficients of all
    /// slices, in slice order (for loops over many slices).
    pub fn forces_and_coefficients(&self) -> (&[f64], &[f64]) {
        (&self.normal_force_n[..self.len()], &self.coefficient)
    }

    /// Normal force of slice `i`, N.
    pub fn normal_force(&self, i: usize) -> f64 {
        self.normal_force_n[i]
    }

    /// Rolling speed of slice `i`, m/s.
    pub fn rolling_speed(&self, i: usize) -> f64 {
        self.rolling_speed_m_s[i]
    }

    /// Sliding speed of slice `i`, m/s.
    pub fn sliding_speed(&self, i: usize) -> f64 {
        self.sliding_speed_m_s[i]
    }

    /// Number of slices.
    pub fn len(&self) -> usize {
        self.contact_of.len()
    }

    /// No slices?
    pub fn is_empty(&self) -> bool {
        self.contact_of.is_empty()
    }

    /// Central and minimum film and Λ of `contact` after [`SliceBatch::evaluate`] (NaN for laws
    /// without a film).
    pub fn film(&self, contact: BatchContact) -> (f64, f64, f64) {
        match &self.contacts[contact.0].prepared {
            Some(p) => (p.film_central_m, p.film_minimum_m, p.lambda),
            None => (f64::NAN, f64::NAN, f64::NAN),
        }
    }

    /// The state of slice `i` as a single contact (for reports and the scuffing check).
    pub fn state(&self, i: usize) -> ContactState {
        let c = &self.contacts[self.contact_of[i]];
        ContactState {
            normal_force_n: self.normal_force_n[i],
            geometry: ContactGeometry::Line {
                length_m: self.length_m[i],
            },
            reduced_radius_m: c.reduced_radius_m,
            reduced_modulus_pa: c.reduced_modulus_pa,
            rolling_speed_m_s: self.rolling_speed_m_s[i],
            sliding_speed_m_s: self.sliding_speed_m_s[i],
            temperature_k: c.temperature_k,
            roughness_ra_m: c.roughness_ra_m,
            film_thickness_m: None,
        }
    }

    /// Traction coefficient of slice `i` after [`SliceBatch::evaluate`].
    pub fn coefficient(&self, i: usize) -> f64 {
        self.coefficient[i]
    }

    /// Evaluates the traction coefficient of every slice with `model` (the model whose
    /// [`SliceBatch::add_contact`] prepared the contacts). Equal to
    /// `traction_prepared(prepared, state(i)).coefficient` for the lubricated laws and to
    /// `traction(state(i), model).coefficient` otherwise.
    pub fn evaluate(&mut self, model: &TractionModel) {
        self.films.compute(model, &mut self.contacts);
        let n = self.len();
        self.coefficient.clear();
        self.coefficient.resize(n, 0.0);
        let (FrictionLaw::Lubricated(lf), Some(oil)) = (&model.cfg.law, model.cfg.oil.as_ref())
        else {
            for i in 0..n {
                self.coefficient[i] = traction(&self.state(i), model).coefficient;
            }
            return;
        };
        self.lanes
            .gather(lf, &self.contacts, &self.contact_runs, self.len());
        let slices = Slices {
            lanes: &self.lanes,
            normal_force_n: &self.normal_force_n,
            length_m: &self.length_m,
            rolling_speed_m_s: &self.rolling_speed_m_s,
            sliding_speed_m_s: &self.sliding_speed_m_s,
        };
        let out = &mut self.coefficient;
        let cfg = &model.cfg;
        // The common laws get a loop in which the law's variants are compile-time constants, so
        // that the compiler sees a branch-free body and vectorises it.
        match (&lf.hydrodynamic, lf.boundary) {
            (Hydrodynamic::Muraki(ms), BoundaryFriction::Kragelsky)
                if ms.small_shear_rate == SmallShearRate::Asinh
                    && ms.piezo == PiezoViscosity::Barus =>
            {
                let solid = ms.solid;
                match (ms.rheology, lf.mixed) {
                    (Rheology::ViscoElastic, Some(lim)) => {
                        evaluate_muraki::<true>(&slices, oil, cfg, solid, Some(lim), out)
                    }
                    (Rheology::ViscoElastic, None) => {
                        evaluate_muraki::<true>(&slices, oil, cfg, solid, None, out)
                    }
                    (Rheology::Isothermal, mixed) => {
                        evaluate_muraki::<false>(&slices, oil, cfg, solid, mixed, out)
                    }
                    _ => evaluate_lubricated(lf, oil, cfg, &slices, out),
                }
            }
            _ => evaluate_lubricated(lf, oil, cfg, &slices, out),
        }
    }
}

/// The slice columns of a [`SliceBatch`], writable in place ([`SliceBatch::columns_mut`]).
#[derive(Debug)]
pub struct SliceColumnsMut<'a> {
    /// normal force, N
    pub normal_force_n: &'a mut [f64],
    /// slice length, m
    pub length_m: &'a mut [f64],
    /// rolling (entrainment) speed, m/s
    pub rolling_speed_m_s: &'a mut [f64],
    /// sliding speed, m/s (the coefficient takes its sign)
    pub sliding_speed_m_s: &'a mut [f64],
}

/// The arrays of a batch read by the evaluation loops.
struct Slices<'a> {
    lanes: &'a ContactLanes,
    normal_force_n: &'a [f64],
    length_m: &'a [f64],
    rolling_speed_m_s: &'a [f64],
    sliding_speed_m_s: &'a [f64],
}

/// Inputs of the rigid–piezoviscous line films left to the batch
/// ([`TractionModel::prepare_contact_deferred`]), one row per contact, as separate columns for
/// [`rigid_piezoviscous_line_many`].
#[derive(Debug, Clone, Default)]
struct PendingFilms {
    contact: Vec<usize>,
    eta0: Vec<f64>,
    alpha: Vec<f64>,
    rolling_speed: Vec<f64>,
    load: Vec<f64>,
    length: Vec<f64>,
    modulus: Vec<f64>,
    radius: Vec<f64>,
    film: Vec<f64>,
}

impl PendingFilms {
    fn clear(&mut self) {
        self.contact.clear();
        for column in self.columns() {
            column.clear();
        }
    }

    fn columns(&mut self) -> [&mut Vec<f64>; 8] {
        [
            &mut self.eta0,
            &mut self.alpha,
            &mut self.rolling_speed,
            &mut self.load,
            &mut self.length,
            &mut self.modulus,
            &mut self.radius,
            &mut self.film,
        ]
    }

    fn push(&mut self, contact: usize, props: &HotProps, whole: &ContactState) {
        self.contact.push(contact);
        let row = [
            props.eta0,
            props.alpha,
            whole.rolling_speed_m_s.abs(),
            whole.normal_force_n,
            whole.geometry.length_m(),
            whole.reduced_modulus_pa,
            whole.reduced_radius_m,
            f64::NAN,
        ];
        for (column, value) in self.columns().into_iter().zip(row) {
            column.push(value);
        }
    }

    /// Computes every pending film and completes its contact (starvation factor and Λ of the
    /// model), as [`TractionModel::prepare_contact`] would have; then empties the list.
    fn compute(&mut self, model: &TractionModel, contacts: &mut [Contact]) {
        rigid_piezoviscous_line_many(
            &self.eta0,
            &self.alpha,
            &self.rolling_speed,
            &self.load,
            &self.length,
            &self.modulus,
            &self.radius,
            &mut self.film,
        );
        let starvation = model.cfg.film.starvation_factor;
        for (&k, &h) in self.contact.iter().zip(&self.film) {
            let c = &mut contacts[k];
            if let Some(p) = c.prepared.as_mut() {
                let h = h * starvation;
                model.set_film(p, h, h, c.roughness_ra_m);
            }
        }
        self.clear();
    }
}

/// Per-slice copies of their contact's data ([`ContactTraction`] and the line stiffness
/// π E'/(2 R')), so that the main loop reads contiguous arrays. Each contact's row is computed
/// once (its divisions included) and then copied to its slices.
///
/// Kept columns: when every prepared contact has the same temperature, R' and E' (one raceway
/// of the dynamics), the columns that depend on nothing else ([`LaneValues::OIL`]) hold one
/// value for all slices. `kept` remembers, per column, the bit pattern of that value and how
/// many slots it fills; the next [`ContactLanes::gather`] with the same bits (compared as bits,
/// so that NaN and −0 count as themselves) and no more slices leaves the column as it is. On
/// 2002834 this skips 7 of the 13 column fills of every right-hand side.
#[derive(Debug, Clone, Default)]
struct ContactLanes {
    rows: Vec<LaneValues<f64>>,
    /// the contact is prepared (lubricated and loaded)
    prepared: Vec<bool>,
    /// one column per value, at least [`FILL_WIDTH`] longer than the batch
    columns: LaneValues<Vec<f64>>,
    /// per column: the bits of the value that fills its first `len` slots, if it is uniform
    kept: LaneValues<Option<(u64, usize)>>,
}

/// One value per column of [`ContactLanes`]: the line stiffness, Λ, the blend weight and the
/// fields of [`MurakiContact`] (η0, ᾱ, Γ, 1/Γ, τ0, β0, h, 1/(τ0 h), τ0² h, h/(12 K_f)).
#[derive(Debug, Clone, Copy, Default)]
struct LaneValues<T> {
    stiffness: T,
    lambda: T,
    mixed_weight: T,
    eta0: T,
    alpha: T,
    shear_modulus: T,
    inv_shear_modulus: T,
    tau0: T,
    beta0: T,
    film: T,
    inv_tau0_film: T,
    tau0_sq_film: T,
    film_conduction: T,
}

impl<T> LaneValues<T> {
    /// Which columns depend only on the contact's temperature (the oil properties), R' and E'
    /// (the line stiffness).
    const OIL: LaneValues<bool> = LaneValues {
        stiffness: true,
        lambda: false,
        mixed_weight: false,
        eta0: true,
        alpha: true,
        shear_modulus: true,
        inv_shear_modulus: true,
        tau0: true,
        beta0: true,
        film: false,
        inv_tau0_film: false,
        tau0_sq_film: false,
        film_conduction: false,
    };

    /// Every value, in declaration order (for the fills that treat all columns alike).
    fn each(&self) -> [&T; 13] {
        [
            &self.stiffness,
            &self.lambda,
            &self.mixed_weight,
            &self.eta0,
            &self.alpha,
            &self.shear_modulus,
            &self.inv_shear_modulus,
            &self.tau0,
            &self.beta0,
            &self.film,
            &self.inv_tau0_film,
            &self.tau0_sq_film,
            &self.film_conduction,
        ]
    }

    /// [`LaneValues::each`], writable.
    fn each_mut(&mut self) -> [&mut T; 13] {
        [
            &mut self.stiffness,
            &mut self.lambda,
            &mut self.mixed_weight,
            &mut self.eta0,
            &mut self.alpha,
            &mut self.shear_modulus,
            &mut self.inv_shear_modulus,
            &mut self.tau0,
            &mut self.beta0,
            &mut self.film,
            &mut self.inv_tau0_film,
            &mut self.tau0_sq_film,
            &mut self.film_conduction,
        ]
    }
}

impl LaneValues<Vec<f64>> {
    /// Copies each value of `row` into the slots `groups` (whole groups of [`FILL_WIDTH`]) of
    /// its column, unless the column is kept. One line per column: the compiler sees thirteen
    /// independent fills with their value in a register.
    fn fill_groups(
        &mut self,
        kept: &LaneValues<Option<(u64, usize)>>,
        groups: std::ops::Range<usize>,
        row: &LaneValues<f64>,
    ) {
        let fill = |column: &mut Vec<f64>, kept: Option<(u64, usize)>, value: f64| {
            if kept.is_none() {
                for group in column[groups.clone()].as_chunks_mut::<FILL_WIDTH>().0 {
                    *group = [value; FILL_WIDTH];
                }
            }
        };
        fill(&mut self.stiffness, kept.stiffness, row.stiffness);
        fill(&mut self.lambda, kept.lambda, row.lambda);
        fill(&mut self.mixed_weight, kept.mixed_weight, row.mixed_weight);
        fill(&mut self.eta0, kept.eta0, row.eta0);
        fill(&mut self.alpha, kept.alpha, row.alpha);
        fill(
            &mut self.shear_modulus,
            kept.shear_modulus,
            row.shear_modulus,
        );
        let inv_shear_modulus = row.inv_shear_modulus;
        fill(
            &mut self.inv_shear_modulus,
            kept.inv_shear_modulus,
            inv_shear_modulus,
        );
        fill(&mut self.tau0, kept.tau0, row.tau0);
        fill(&mut self.beta0, kept.beta0, row.beta0);
        fill(&mut self.film, kept.film, row.film);
        fill(
            &mut self.inv_tau0_film,
            kept.inv_tau0_film,
            row.inv_tau0_film,
        );
        fill(&mut self.tau0_sq_film, kept.tau0_sq_film, row.tau0_sq_film);
        let conduction = row.film_conduction;
        fill(&mut self.film_conduction, kept.film_conduction, conduction);
    }
}

/// Slices written per store when a contact's value is copied to its slices: whole groups of
/// this many, so that a copy may run up to `FILL_WIDTH − 1` slices into the next contact's,
/// which are written afterwards.
const FILL_WIDTH: usize = 8;

/// A contact's values of the [`ContactLanes`] columns.
fn lane_row(line_stiffness: f64, ct: &ContactTraction) -> LaneValues<f64> {
    let m = &ct.muraki;
    LaneValues {
        stiffness: line_stiffness,
        lambda: ct.lambda,
        mixed_weight: ct.mixed_weight,
        eta0: m.eta0,
        alpha: m.alpha,
        shear_modulus: m.shear_modulus,
        inv_shear_modulus: m.inv_shear_modulus,
        tau0: m.tau0,
        beta0: m.beta0,
        film: m.film,
        inv_tau0_film: m.inv_tau0_film,
        tau0_sq_film: m.tau0_sq_film,
        film_conduction: m.film_conduction,
    }
}

impl ContactLanes {
    /// Fills the columns for the `n` slices of `contacts`, whose runs of consecutive slices
    /// are `runs` ((contact, first slice), in slice order).
    fn gather(
        &mut self,
        lf: &LubricatedFriction,
        contacts: &[Contact],
        runs: &[(usize, usize)],
        n: usize,
    ) {
        self.rows.clear();
        self.rows.extend(contacts.iter().map(|c| {
            let stiffness = line_stiffness(c.reduced_modulus_pa, c.reduced_radius_m);
            match &c.prepared {
                Some(p) => lane_row(
                    stiffness,
                    &ContactTraction::new(lf, &p.props, p.film_central_m, p.lambda),
                ),
                None => lane_row(stiffness, &ContactTraction::default()),
            }
        }));
        // the prepared contacts (the others only ever meet a zero coefficient) and whether
        // they share the inputs of the oil columns
        let mut prepared = contacts
            .iter()
            .enumerate()
            .filter(|(_, c)| c.prepared.is_some());
        let first = prepared.next();
        let same_oil = first.is_some_and(|(_, a)| {
            prepared.all(|(_, b)| {
                a.temperature_k.to_bits() == b.temperature_k.to_bits()
                    && a.reduced_radius_m.to_bits() == b.reduced_radius_m.to_bits()
                    && a.reduced_modulus_pa.to_bits() == b.reduced_modulus_pa.to_bits()
            })
        });
        let room = n + FILL_WIDTH;
        self.prepared.clear();
        self.prepared.resize(room, false);
        let oil = LaneValues::<f64>::OIL;
        let uniform_row = first.map(|(k, _)| self.rows[k]);
        let columns = self
            .columns
            .each_mut()
            .into_iter()
            .zip(self.kept.each_mut());
        for (c, (column, kept)) in columns.enumerate() {
            if column.len() < room {
                column.resize(room, 0.0);
                *kept = None;
            }
            let uniform = match &uniform_row {
                Some(row) if same_oil && *oil.each()[c] => Some(row.each()[c].to_bits()),
                _ => None,
            };
            match (uniform, *kept) {
                (Some(bits), Some((kept_bits, len))) if bits == kept_bits && len >= n => {}
                (Some(bits), _) => {
                    column[..n].fill(f64::from_bits(bits));
                    *kept = Some((bits, n));
                }
                (None, _) => *kept = None,
            }
        }
        // a run's values are copied in whole groups of FILL_WIDTH slices, run after run
        for (r, &(k, start)) in runs.iter().enumerate() {
            let end = runs.get(r + 1).map_or(n, |&(_, next)| next);
            let groups = start..start + (end - start).div_ceil(FILL_WIDTH) * FILL_WIDTH;
            let row = &self.rows[k];
            for group in self.prepared[groups.clone()]
                .as_chunks_mut::<FILL_WIDTH>()
                .0
            {
                *group = [contacts[k].prepared.is_some(); FILL_WIDTH];
            }
            self.columns.fill_groups(&self.kept, groups, row);
        }
    }
}

rolldyn_numerics::avx512_twin! {
    /// [`evaluate_lubricated`] for Muraki (visco-elastic when `THERMAL`, else isothermal) with
    /// L = sinh⁻¹σ, Barus viscosity and Kragelsky boundary friction: the law is rebuilt here from
    /// constant variants, so every `match` on it folds away and the loop body is branch-free.
    ///
    /// On x86-64 the loop is also compiled for AVX-512F (eight lanes; two independent 256-bit
    /// chains per iteration on CPUs that split 512-bit operations, which hides the latency of
    /// this long loop body), chosen at run time on CPUs that have it. Both give the same bits: Rust never fuses a multiply and an
    /// add on its own, and `+ − × ÷ √`, `min`/`max` and comparisons are exact in every width.
    fn evaluate_muraki<const THERMAL: bool>(
        slices: &Slices,
        oil: &Lubricant,
        cfg: &TractionConfig,
        solid: SolidThermal,
        mixed: Option<MixedLimits>,
        out: &mut [f64],
    ) = evaluate_muraki_portable / evaluate_muraki_avx512 {
        let rheology = if THERMAL {
            Rheology::ViscoElastic
        } else {
            Rheology::Isothermal
        };
        let law = |mixed| LubricatedFriction {
            hydrodynamic: Hydrodynamic::Muraki(MurakiSettings {
                rheology,
                small_shear_rate: SmallShearRate::Asinh,
                solid,
                piezo: PiezoViscosity::Barus,
            }),
            boundary: BoundaryFriction::Kragelsky,
            mixed,
        };
        match mixed {
            Some(lim) => evaluate_lubricated(&law(Some(lim)), oil, cfg, slices, out),
            None => evaluate_lubricated(&law(None), oil, cfg, slices, out),
        }
    }
}

/// The loop of [`SliceBatch::evaluate`] for the lubricated laws: every input a contiguous
/// array, the law loop-invariant, no calls.
#[inline(always)]
fn evaluate_lubricated(
    lf: &LubricatedFriction,
    oil: &Lubricant,
    cfg: &TractionConfig,
    slices: &Slices,
    coefficient: &mut [f64],
) {
    let n = coefficient.len();
    let lanes = slices.lanes;
    let (normal_force_n, length_m) = (&slices.normal_force_n[..n], &slices.length_m[..n]);
    let rolling = &slices.rolling_speed_m_s[..n];
    let sliding = &slices.sliding_speed_m_s[..n];
    let prepared = &lanes.prepared[..n];
    let c = &lanes.columns;
    let (stiffness, lambda, weight) = (&c.stiffness[..n], &c.lambda[..n], &c.mixed_weight[..n]);
    let (eta0, alpha, tau0, beta0) = (&c.eta0[..n], &c.alpha[..n], &c.tau0[..n], &c.beta0[..n]);
    let (gamma, inv_gamma) = (&c.shear_modulus[..n], &c.inv_shear_modulus[..n]);
    let (film, inv_tau0_film) = (&c.film[..n], &c.inv_tau0_film[..n]);
    let (tau0_sq_film, conduction) = (&c.tau0_sq_film[..n], &c.film_conduction[..n]);
    for i in 0..n {
        let contact = ContactTraction {
            muraki: MurakiContact {
                eta0: eta0[i],
                alpha: alpha[i],
                shear_modulus: gamma[i],
                inv_shear_modulus: inv_gamma[i],
                tau0: tau0[i],
                beta0: beta0[i],
                film: film[i],
                inv_tau0_film: inv_tau0_film[i],
                tau0_sq_film: tau0_sq_film[i],
                film_conduction: conduction[i],
            },
            lambda: lambda[i],
            mixed_weight: weight[i],
        };
        let q = normal_force_n[i];
        let v = sliding[i];
        let u_eff = rolling[i].abs().max(cfg.min_rolling_speed_m_s);
        let (pressure, inv_rolling_speed) =
            SlicePressure::line_with_speed(q, length_m[i], stiffness[i], u_eff);
        let slice = MurakiSlice {
            pressure,
            rolling_speed: u_eff,
            inv_rolling_speed,
            sliding_speed: v.abs(),
        };
        let parts = lubricated_coefficient(lf, oil, &contact, &slice);
        let mu = parts.mu * cfg.sliding_sign(v);
        coefficient[i] = if prepared[i] && q > 0.0 { mu } else { 0.0 };
    }
}
