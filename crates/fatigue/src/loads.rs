//! The cage-load export (SPEC §7.2, docs/outputs.md "Cage loads"): one steady cage revolution
//! as 180 load sets (2° of cage rotation apart), each with every contact force on the cage and
//! its point of application in cage coordinates ([`crate::cage`]), and the cage's rigid-body
//! motion. Written as a Parquet table of contact rows plus a small JSON header, SI units, so a
//! user's own finite-element model can read it too.

use crate::cage::CageGeometry;
use crate::cage_material::CageMaterial;
use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::Field;
use rolldyn_geometry::RetainingLip;
use rolldyn_output::mixed_table::{Column, Values, write_parquet_table};
use rolldyn_output::non_finite::{NON_FINITE_KEY, default_reason};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The kind of a contact on the cage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactKind {
    /// roller ↔ bar flank; `location` 0…3 = (side −, end 0), (side −, end 1), (side +, end 0),
    /// (side +, end 1)
    Bar,
    /// roller end ↔ pocket face; `location` 0: the face at `z < 0`, 1: at `z > 0`
    PocketEnd,
    /// cage ↔ guiding land; `location` = land station (0: `z < 0`); `pocket` = nearest pocket
    Land,
}

impl ContactKind {
    fn name(self) -> &'static str {
        match self {
            ContactKind::Bar => "bar",
            ContactKind::PocketEnd => "pocket_end",
            ContactKind::Land => "land",
        }
    }

    fn parse(text: &str) -> Option<Self> {
        [ContactKind::Bar, ContactKind::PocketEnd, ContactKind::Land]
            .into_iter()
            .find(|k| k.name() == text)
    }
}

/// One contact force on the cage, cage coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ContactLoad {
    pub kind: ContactKind,
    pub pocket: usize,
    pub location: usize,
    /// force on the cage, N
    pub force_n: [f64; 3],
    /// point of application, m
    pub point_m: [f64; 3],
}

/// One load set: the cage at one angle of the revolution.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LoadSet {
    /// cage rotation since the first set, degrees
    pub cage_angle_deg: f64,
    /// simulation time, s
    pub time_s: f64,
    /// acceleration of the cage centre, cage coordinates, m/s²
    pub acceleration_m_s2: [f64; 3],
    /// angular velocity, cage coordinates, rad/s
    pub angular_velocity_rad_s: [f64; 3],
    /// angular acceleration, cage coordinates, rad/s²
    pub angular_acceleration_rad_s2: [f64; 3],
    /// contact forces (only those with contact)
    #[serde(skip)]
    pub contacts: Vec<ContactLoad>,
}

/// What the JSON header says besides the sets.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ExportHeader {
    /// "rolldyn-cage-loads"
    pub format: String,
    pub version: u32,
    /// "SI: N, m, s, rad; angles of sets in degrees"
    pub units: String,
    /// the model the loads come from
    pub model: String,
    pub cage: CageGeometry,
    /// the cage's material and plating, whose S–N curve the fatigue run uses (absent in exports
    /// written before the materials carried fatigue data)
    #[serde(default)]
    pub cage_material: Option<CageMaterial>,
    /// axial position (±) of the roller ↔ bar evaluation points, m
    pub bar_station_z_m: f64,
    /// mean cage speed over the revolution, rpm
    pub cage_speed_rpm: f64,
}

/// A cage-load export: header and load sets.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CageLoadExport {
    pub header: ExportHeader,
    pub sets: Vec<LoadSet>,
}

/// Format name and version written to the header.
pub const FORMAT: &str = "rolldyn-cage-loads";
pub const VERSION: u32 = 2;

/// The header file beside a load table: `loads.parquet` → `loads.json` (any other name gets
/// `.json` appended).
pub fn header_path(table: &Path) -> PathBuf {
    match table.extension() {
        Some(e) if e == "parquet" => table.with_extension("json"),
        _ => {
            let mut name = table.as_os_str().to_owned();
            name.push(".json");
            PathBuf::from(name)
        }
    }
}

impl CageLoadExport {
    /// Writes the contact table to `table` (Parquet) and the header to [`header_path`].
    pub fn write(&self, table: &Path) -> Result<(), String> {
        let rows: Vec<(usize, &ContactLoad)> = self
            .sets
            .iter()
            .enumerate()
            .flat_map(|(i, s)| s.contacts.iter().map(move |c| (i, c)))
            .collect();
        let number = |f: &dyn Fn(usize, &ContactLoad) -> f64| -> Vec<f64> {
            rows.iter().map(|&(i, c)| f(i, c)).collect()
        };
        let kind: Vec<Option<String>> = rows
            .iter()
            .map(|(_, c)| Some(c.kind.name().to_string()))
            .collect();
        let numbers: Vec<(&str, Vec<f64>)> = vec![
            ("set", number(&|i, _| i as f64)),
            ("pocket", number(&|_, c| c.pocket as f64)),
            ("location", number(&|_, c| c.location as f64)),
            ("fx_n", number(&|_, c| c.force_n[0])),
            ("fy_n", number(&|_, c| c.force_n[1])),
            ("fz_n", number(&|_, c| c.force_n[2])),
            ("x_m", number(&|_, c| c.point_m[0])),
            ("y_m", number(&|_, c| c.point_m[1])),
            ("z_m", number(&|_, c| c.point_m[2])),
        ];
        let mut columns = vec![Column {
            name: "kind",
            values: Values::Text(&kind),
        }];
        columns.extend(numbers.iter().map(|(name, v)| Column {
            name,
            values: Values::Numbers(v),
        }));
        write_parquet_table(table, &columns).map_err(|e| e.to_string())?;
        let header = header_path(table);
        let json = serde_json::to_string_pretty(self).map_err(|e| e.to_string())?;
        std::fs::write(&header, json).map_err(|e| format!("{}: {e}", header.display()))
    }

    /// Reads an export written by [`CageLoadExport::write`].
    pub fn read(table: &Path) -> Result<Self, String> {
        let header = header_path(table);
        let text =
            std::fs::read_to_string(&header).map_err(|e| format!("{}: {e}", header.display()))?;
        let mut export: CageLoadExport =
            serde_json::from_str(&text).map_err(|e| format!("{}: {e}", header.display()))?;
        if export.header.format != FORMAT || export.header.version != VERSION {
            return Err(format!(
                "{}: not a {FORMAT} v{VERSION} header",
                header.display()
            ));
        }
        export
            .check_header()
            .map_err(|e| e.located(&header, &text).to_string())?;
        let limits = RowLimits::of(&export.header.cage);
        for (set, contact) in read_contacts(table, &limits)? {
            let sets = export.sets.len();
            let target = export.sets.get_mut(set).ok_or_else(|| {
                format!("{}: set {set} beyond the header's {sets}", table.display())
            })?;
            target.contacts.push(contact);
        }
        Ok(export)
    }
}

/// Largest contact force on the cage, N: 10⁸ N (10 000 t) is beyond the radial rating of the
/// largest rolling bearings (≈ 10⁷ N), let alone a force on their cage.
pub const MAX_CONTACT_FORCE_N: f64 = 1e8;
/// Largest acceleration of the cage centre, m/s²: 10⁸ m/s² (10⁷ g), far beyond any shock a
/// bearing survives (shock tests stop near 10⁴ g).
pub const MAX_CAGE_ACCELERATION_M_S2: f64 = 1e8;
/// Shortest time, s, in which a cage may reach its largest plausible speed from rest: an
/// angular acceleration above ω_max / 1 µs is refused (a roller–cage impact lasts ≥ 10 µs).
pub const MIN_CAGE_SPEED_UP_S: f64 = 1e-6;
/// Largest outside radius of a cage, m (the largest rolling bearings are ≈ 8 m in diameter).
pub const MAX_CAGE_OUTER_RADIUS_M: f64 = 5.0;
/// Most load sets of an export (a set per 0.01° of cage rotation; rolldyn writes 180).
pub const MAX_LOAD_SETS: usize = 36_000;

/// A header value out of its bounds: the key (`sets[3].angular_velocity_rad_s`), which
/// occurrence of its last name in the file it is, and why.
struct HeaderError {
    key: String,
    occurrence: usize,
    reason: String,
}

impl HeaderError {
    /// The error naming the header file, the line and column of the key, and the key.
    fn located(self, header: &Path, text: &str) -> rolldyn_model::ModelError {
        let name = self.key.rsplit(['.', ']']).next().unwrap_or(&self.key);
        let position = json_key_position(text, name, self.occurrence);
        rolldyn_model::ModelError {
            file: header.display().to_string(),
            position,
            key: self.key,
            reason: self.reason,
        }
    }
}

/// 1-based line and column of the `occurrence`-th (0-based) key `"name":` of a JSON text.
fn json_key_position(text: &str, name: &str, occurrence: usize) -> Option<(usize, usize)> {
    let quoted = format!("\"{name}\"");
    let offset = text
        .match_indices(&quoted)
        .filter(|(at, _)| {
            !text[..*at].ends_with('\\') && text[at + quoted.len()..].trim_start().starts_with(':')
        })
        .nth(occurrence)?
        .0;
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    Some((line, column))
}

/// Largest speed of the cage, rad/s: the surface-speed bound of the model's speeds
/// ([`rolldyn_model::bounds::MAX_PITCH_SURFACE_SPEED_M_S`]) at its pitch radius.
fn max_cage_speed(cage: &CageGeometry) -> f64 {
    rolldyn_model::bounds::MAX_PITCH_SURFACE_SPEED_M_S / cage.pitch_radius
}

/// The length of `v` (without overflow for the largest finite components).
fn norm(v: &[f64; 3]) -> f64 {
    v[0].hypot(v[1]).hypot(v[2])
}

impl CageLoadExport {
    /// Checks every value of the header against its physical bounds (docs/outputs.md, "Cage
    /// loads"): the cage's dimensions and material, then each set's motion.
    fn check_header(&self) -> Result<(), HeaderError> {
        let bad = |key: &str, occurrence: usize, reason: String| HeaderError {
            key: key.to_string(),
            occurrence,
            reason,
        };
        let h = &self.header;
        let c = &h.cage;
        if !(c.outer_radius > 0.0 && c.outer_radius <= MAX_CAGE_OUTER_RADIUS_M) {
            return Err(bad(
                "header.cage.outer_radius",
                0,
                format!(
                    "{:e} m is implausible: a cage's outside radius is > 0 and at most {MAX_CAGE_OUTER_RADIUS_M} m (the largest bearings are ≈ 8 m in diameter)",
                    c.outer_radius
                ),
            ));
        }
        let size = 2.0 * c.outer_radius;
        let lip =
            |l: &Option<RetainingLip>| l.map_or([0.0; 3], |l| [l.diameter, l.window, l.tip_radius]);
        let [od, ow, ot] = lip(&c.pocket.outer_lip);
        let [id, iw, it] = lip(&c.pocket.inner_lip);
        // the inner lip's keys follow the outer lip's of the same names
        let inner = usize::from(c.pocket.outer_lip.is_some());
        let lengths = [
            ("header.cage.inner_radius", 0, c.inner_radius),
            ("header.cage.width", 0, c.width),
            ("header.cage.roller_radius", 0, c.roller_radius),
            ("header.cage.pitch_radius", 0, c.pitch_radius),
            ("header.cage.pocket.axial", 0, c.pocket.axial),
            (
                "header.cage.pocket.fillet_radius",
                0,
                c.pocket.fillet_radius,
            ),
            (
                "header.cage.pocket.face_clearance",
                0,
                c.pocket.face_clearance,
            ),
            ("header.cage.pocket.outer_lip.diameter", 0, od),
            ("header.cage.pocket.outer_lip.window", 0, ow),
            ("header.cage.pocket.outer_lip.tip_radius", 0, ot),
            ("header.cage.pocket.inner_lip.diameter", inner, id),
            ("header.cage.pocket.inner_lip.window", inner, iw),
            ("header.cage.pocket.inner_lip.tip_radius", inner, it),
            ("header.cage.bar_contact", 0, c.bar_contact[0]),
            ("header.cage.bar_contact", 0, c.bar_contact[1]),
            ("header.bar_station_z_m", 0, h.bar_station_z_m),
        ];
        for (key, occurrence, value) in lengths {
            if !(..=size).contains(&value.abs()) {
                return Err(bad(
                    key,
                    occurrence,
                    format!(
                        "{value:e} m is implausible: no length of a cage exceeds its outside \
                         diameter {size:e} m"
                    ),
                ));
            }
        }
        for (key, value) in [
            ("header.cage.inner_radius", c.inner_radius),
            ("header.cage.width", c.width),
            ("header.cage.roller_radius", c.roller_radius),
            ("header.cage.pitch_radius", c.pitch_radius),
        ] {
            if value <= 0.0 {
                return Err(bad(key, 0, format!("{value:e} m: must be positive")));
            }
        }
        if !(1..=1000).contains(&c.pockets) {
            return Err(bad(
                "header.cage.pockets",
                0,
                format!("{}: a cage has 1…1000 pockets", c.pockets),
            ));
        }
        let (lo, hi) = rolldyn_geometry::plausible::YOUNGS_MODULUS_RANGE_PA;
        if !(lo..=hi).contains(&c.youngs_modulus) {
            return Err(bad(
                "header.cage.youngs_modulus",
                0,
                format!(
                    "{:e} Pa is implausible (engineering solids: {lo:e}…{hi:e} Pa)",
                    c.youngs_modulus
                ),
            ));
        }
        let (lo, hi) = rolldyn_geometry::plausible::DENSITY_RANGE_KG_M3;
        if !(lo..=hi).contains(&c.density) {
            return Err(bad(
                "header.cage.density",
                0,
                format!(
                    "{:e} kg/m³ is implausible (engineering solids: {lo:e}…{hi:e} kg/m³)",
                    c.density
                ),
            ));
        }
        if !(c.poisson_ratio > -1.0 && c.poisson_ratio < 0.5) {
            return Err(bad(
                "header.cage.poisson_ratio",
                0,
                format!("{}: must lie in (−1, 0.5)", c.poisson_ratio),
            ));
        }
        let max_speed = max_cage_speed(c);
        let rpm = 30.0 / std::f64::consts::PI;
        let speed_reason = |speed: f64| {
            format!(
                "{:e} rad/s is implausible: more than {max_speed:.4e} rad/s ({:.0} rpm), a surface speed of {} m/s at the pitch radius {:e} m",
                speed,
                max_speed * rpm,
                rolldyn_model::bounds::MAX_PITCH_SURFACE_SPEED_M_S,
                c.pitch_radius
            )
        };
        if !(..=max_speed * rpm).contains(&h.cage_speed_rpm.abs()) {
            return Err(bad(
                "header.cage_speed_rpm",
                0,
                speed_reason(h.cage_speed_rpm / rpm),
            ));
        }
        if self.sets.is_empty() || self.sets.len() > MAX_LOAD_SETS {
            return Err(bad(
                "sets",
                0,
                format!(
                    "{} load sets: an export holds 1…{MAX_LOAD_SETS}",
                    self.sets.len()
                ),
            ));
        }
        let max_angular_acceleration = max_speed / MIN_CAGE_SPEED_UP_S;
        for (i, set) in self.sets.iter().enumerate() {
            let key = |name: &str| format!("sets[{i}].{name}");
            if !(..=360.0).contains(&set.cage_angle_deg.abs()) {
                return Err(bad(
                    &key("cage_angle_deg"),
                    i,
                    format!(
                        "{}°: a set lies within one revolution (−360…360°)",
                        set.cage_angle_deg
                    ),
                ));
            }
            if !(set.time_s >= 0.0 && set.time_s.is_finite()) {
                return Err(bad(
                    &key("time_s"),
                    i,
                    format!("{} s: must be finite and ≥ 0", set.time_s),
                ));
            }
            let speed = norm(&set.angular_velocity_rad_s);
            if !(..=max_speed).contains(&speed) {
                return Err(bad(&key("angular_velocity_rad_s"), i, speed_reason(speed)));
            }
            let alpha = norm(&set.angular_acceleration_rad_s2);
            if !(..=max_angular_acceleration).contains(&alpha) {
                return Err(bad(
                    &key("angular_acceleration_rad_s2"),
                    i,
                    format!(
                        "{alpha:e} rad/s² is implausible: more than {max_angular_acceleration:.4e} rad/s², the largest cage speed reached from rest in {MIN_CAGE_SPEED_UP_S:e} s"
                    ),
                ));
            }
            let a = norm(&set.acceleration_m_s2);
            if !(..=MAX_CAGE_ACCELERATION_M_S2).contains(&a) {
                return Err(bad(
                    &key("acceleration_m_s2"),
                    i,
                    format!(
                        "{a:e} m/s² is implausible: more than {MAX_CAGE_ACCELERATION_M_S2:e} m/s² (10⁷ g; bearing shock tests stop near 10⁴ g)"
                    ),
                ));
            }
        }
        Ok(())
    }
}

/// The bounds of a contact row of an export of `cage`.
struct RowLimits {
    pockets: usize,
    /// largest distance of a point of application from the cage axis, m
    radius_m: f64,
    /// largest axial coordinate of a point of application, m
    axial_m: f64,
}

impl RowLimits {
    fn of(cage: &CageGeometry) -> Self {
        Self {
            pockets: cage.pockets,
            radius_m: 2.0 * cage.outer_radius,
            axial_m: cage.width,
        }
    }

    /// Why a contact is implausible (the column at fault and the reason), if it is.
    fn check(&self, c: &ContactLoad) -> Result<(), (&'static str, String)> {
        if c.pocket >= self.pockets {
            return Err((
                "pocket",
                format!("{}: the cage has {} pockets", c.pocket, self.pockets),
            ));
        }
        let locations = match c.kind {
            ContactKind::Bar => 4,
            ContactKind::PocketEnd | ContactKind::Land => 2,
        };
        if c.location >= locations {
            return Err((
                "location",
                format!(
                    "{}: a {} contact has locations 0…{}",
                    c.location,
                    c.kind.name(),
                    locations - 1
                ),
            ));
        }
        for (column, f) in ["fx_n", "fy_n", "fz_n"].into_iter().zip(c.force_n) {
            if f.abs() > MAX_CONTACT_FORCE_N {
                return Err((
                    column,
                    format!(
                        "{f:e} N is implausible: more than {MAX_CONTACT_FORCE_N:e} N (10 000 t; the largest bearings are rated ≈ 10⁷ N)"
                    ),
                ));
            }
        }
        let [x, y, z] = c.point_m;
        if x.hypot(y) > self.radius_m {
            let column = if x.abs() > y.abs() { "x_m" } else { "y_m" };
            return Err((
                column,
                format!(
                    "({x:e}, {y:e}) m lies {:e} m from the cage axis: a point on the cage lies within twice its outside radius, {:e} m",
                    x.hypot(y),
                    self.radius_m
                ),
            ));
        }
        if z.abs() > self.axial_m {
            return Err((
                "z_m",
                format!(
                    "{z:e} m: a point on the cage lies axially within its width, {:e} m",
                    self.axial_m
                ),
            ));
        }
        Ok(())
    }
}

/// Refuses a table whose footer places a column chunk outside the file's `file_bytes` (a damaged
/// file): the Parquet reader asserts on a negative extent instead of returning an error.
fn check_column_extents(
    reader: &SerializedFileReader<std::fs::File>,
    file_bytes: u64,
) -> Result<(), String> {
    for group in reader.metadata().row_groups() {
        for column in group.columns() {
            let start = column
                .dictionary_page_offset()
                .unwrap_or(column.data_page_offset());
            let length = column.compressed_size();
            let inside = u64::try_from(start)
                .ok()
                .zip(u64::try_from(length).ok())
                .is_some_and(|(s, l)| s.checked_add(l).is_some_and(|end| end <= file_bytes));
            if !inside {
                return Err(format!(
                    "column {} lies outside the file (offset {start}, {length} bytes): a damaged table",
                    column.column_path()
                ));
            }
        }
    }
    Ok(())
}

/// The contact rows of a load table: (set, contact), each within `limits`; an error names the
/// table, the row (1-based) and the column.
///
/// The Parquet reader asserts on some damaged files instead of returning an error: such a panic
/// is caught and the table refused as damaged.
fn read_contacts(table: &Path, limits: &RowLimits) -> Result<Vec<(usize, ContactLoad)>, String> {
    let fail = |e: &dyn std::fmt::Display| format!("{}: {e}", table.display());
    let file = std::fs::File::open(table).map_err(|e| fail(&e))?;
    let file_bytes = file.metadata().map_err(|e| fail(&e))?.len();
    let reader = SerializedFileReader::new(file).map_err(|e| fail(&e))?;
    check_column_extents(&reader, file_bytes).map_err(|e| fail(&e))?;
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        contact_rows(table, &reader, limits)
    }))
    .unwrap_or_else(|_| Err(fail(&"the Parquet reader failed on a damaged table")))
}

/// The contact rows of the opened load `table`, as [`read_contacts`] returns them.
fn contact_rows(
    table: &Path,
    reader: &SerializedFileReader<std::fs::File>,
    limits: &RowLimits,
) -> Result<Vec<(usize, ContactLoad)>, String> {
    let fail = |e: &dyn std::fmt::Display| format!("{}: {e}", table.display());
    let rows = reader.get_row_iter(None).map_err(|e| fail(&e))?;
    let mut out = Vec::new();
    for (index, row) in rows.enumerate() {
        let at = |column: &str, reason: &dyn std::fmt::Display| {
            format!(
                "{}: row {}, column {column} — {reason}",
                table.display(),
                index + 1
            )
        };
        let row = row.map_err(|e| fail(&e))?;
        let mut kind = None;
        let mut v = [f64::NAN; 9];
        for (name, field) in row.get_column_iter() {
            match (name.as_str(), field) {
                ("kind", Field::Str(s)) => kind = ContactKind::parse(s),
                (n, Field::Double(x)) => {
                    if let Some(i) = NUMBER_COLUMNS.iter().position(|&m| m == n) {
                        v[i] = *x;
                    }
                }
                _ => {}
            }
        }
        let kind =
            kind.ok_or_else(|| at("kind", &"not a known contact kind (bar, pocket_end, land)"))?;
        if let Some(i) = v.iter().position(|x| !x.is_finite()) {
            return Err(at(NUMBER_COLUMNS[i], &"missing or not a finite number"));
        }
        if let Some(i) = v[..3].iter().position(|x| *x < 0.0 || x.fract() != 0.0) {
            return Err(at(NUMBER_COLUMNS[i], &"must be a whole number ≥ 0"));
        }
        let contact = ContactLoad {
            kind,
            pocket: v[1] as usize,
            location: v[2] as usize,
            force_n: [v[3], v[4], v[5]],
            point_m: [v[6], v[7], v[8]],
        };
        limits
            .check(&contact)
            .map_err(|(column, reason)| at(column, &reason))?;
        out.push((v[0] as usize, contact));
    }
    Ok(out)
}

/// The numeric columns of a load table, in the order of [`read_contacts`]'s values.
const NUMBER_COLUMNS: [&str; 9] = [
    "set", "pocket", "location", "fx_n", "fy_n", "fz_n", "x_m", "y_m", "z_m",
];

/// The largest contact forces of the recorded revolution (seed 000 Table 3.2 columns the
/// correlations of V-27 use), N.
///
/// Serialised with a `non_finite` reason beside a force the revolution did not define (an
/// export holds no roller–raceway force: NaN).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
pub struct RevolutionMaxima {
    pub max_cage_land_force_n: f64,
    pub max_roller_cage_force_n: f64,
    pub max_roller_raceway_force_n: f64,
}

impl Serialize for RevolutionMaxima {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let values = [
            ("max_cage_land_force_n", self.max_cage_land_force_n),
            ("max_roller_cage_force_n", self.max_roller_cage_force_n),
            (
                "max_roller_raceway_force_n",
                self.max_roller_raceway_force_n,
            ),
        ];
        let reasons: BTreeMap<&str, &str> = values
            .iter()
            .filter(|(_, value)| !value.is_finite())
            .map(|&(key, value)| match (key, value.is_nan()) {
                ("max_roller_raceway_force_n", true) => (
                    key,
                    "not recorded: a cage-load export holds no roller–raceway force",
                ),
                _ => (key, default_reason(value)),
            })
            .collect();
        let mut map = serializer.serialize_map(None)?;
        for (key, value) in values {
            map.serialize_entry(key, &value)?;
        }
        if !reasons.is_empty() {
            map.serialize_entry(NON_FINITE_KEY, &reasons)?;
        }
        map.end()
    }
}

impl RevolutionMaxima {
    /// The largest cage–land and roller–cage forces of a load export (the sum of the force
    /// magnitudes at the land stations and at one roller's bar points, per set); an export does
    /// not hold the roller–raceway forces (NaN).
    pub fn of_export(export: &CageLoadExport) -> Self {
        let magnitude = |f: &[f64; 3]| (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
        let mut land: f64 = 0.0;
        let mut bar: f64 = 0.0;
        for set in &export.sets {
            let mut per_pocket = std::collections::BTreeMap::<usize, f64>::new();
            let mut land_set = 0.0;
            for c in &set.contacts {
                match c.kind {
                    ContactKind::Land => land_set += magnitude(&c.force_n),
                    ContactKind::Bar => {
                        *per_pocket.entry(c.pocket).or_default() += magnitude(&c.force_n)
                    }
                    ContactKind::PocketEnd => {}
                }
            }
            land = land.max(land_set);
            bar = per_pocket.values().fold(bar, |a, &b| a.max(b));
        }
        Self {
            max_cage_land_force_n: land,
            max_roller_cage_force_n: bar,
            max_roller_raceway_force_n: f64::NAN,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An export of the 2002834 cage: three sets, bar and land contacts.
    fn export() -> CageLoadExport {
        let cage = crate::cage::tests::cage_2002834();
        let set = |angle: f64, contacts: Vec<ContactLoad>| LoadSet {
            cage_angle_deg: angle,
            time_s: angle * 1e-4,
            acceleration_m_s2: [1.0, 2.0, 3.0],
            angular_velocity_rad_s: [0.0, 0.0, 300.0],
            angular_acceleration_rad_s2: [0.1, 0.2, 0.3],
            contacts,
        };
        let bar = ContactLoad {
            kind: ContactKind::Bar,
            pocket: 2,
            location: 3,
            force_n: [1.5, -20.0, 0.25],
            point_m: [0.055, 0.005, 0.004],
        };
        let land = ContactLoad {
            kind: ContactKind::Land,
            location: 1,
            ..bar
        };
        CageLoadExport {
            header: ExportHeader {
                format: FORMAT.into(),
                version: VERSION,
                units: "SI".into(),
                model: "test".into(),
                cage,
                cage_material: None,
                bar_station_z_m: 0.004,
                cage_speed_rpm: 3000.0,
            },
            sets: vec![
                set(0.0, vec![bar, land]),
                set(2.0, vec![]),
                set(4.0, vec![bar]),
            ],
        }
    }

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("rolldyn-loads-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir.join("loads.parquet")
    }

    #[test]
    fn an_export_reads_back_as_written() {
        let export = export();
        let path = scratch("round-trip");
        export.write(&path).unwrap();
        assert_eq!(CageLoadExport::read(&path).unwrap(), export);
    }

    #[test]
    fn n7_values_out_of_bounds_name_their_line_or_row_and_column() {
        let path = scratch("bounds");
        let mut bad = export();
        bad.sets[1].angular_velocity_rad_s[2] = 1e308;
        bad.write(&path).unwrap();
        let e = CageLoadExport::read(&path).unwrap_err();
        let header = std::fs::read_to_string(header_path(&path)).unwrap();
        let line = header
            .lines()
            .enumerate()
            .filter(|(_, l)| l.contains("\"angular_velocity_rad_s\""))
            .nth(1)
            .unwrap()
            .0
            + 1;
        assert!(
            e.contains(&format!("loads.json:{line}:"))
                && e.contains("sets[1].angular_velocity_rad_s — 1e308 rad/s is implausible"),
            "{e}"
        );
        let mut bad = export();
        bad.sets[2].contacts[0].force_n[1] = -1e12;
        bad.write(&path).unwrap();
        let e = CageLoadExport::read(&path).unwrap_err();
        assert!(
            e.contains("loads.parquet: row 3, column fy_n — -1e12 N"),
            "{e}"
        );
        let mut bad = export();
        bad.sets[0].contacts[1].point_m = [0.0, 0.0, 1.0];
        bad.write(&path).unwrap();
        let e = CageLoadExport::read(&path).unwrap_err();
        assert!(e.contains("row 2, column z_m"), "{e}");
    }

    /// M2 (issue 39 mutation test): a load table whose Parquet footer is damaged is refused
    /// naming the file; it panicked in the Parquet reader (a column chunk of negative extent).
    #[test]
    fn m2_a_damaged_load_table_is_refused_not_a_panic() {
        let table = scratch("m2");
        export().write(&table).unwrap();
        let good = std::fs::read(&table).unwrap();
        // every byte of the footer (its metadata, before the 8-byte length and magic) in turn,
        // set to 0x00, 0x7f or 0xff
        let footer = u32::from_le_bytes(good[good.len() - 8..good.len() - 4].try_into().unwrap());
        let start = good.len() - 8 - footer as usize;
        for at in start..good.len() - 8 {
            let byte = [0x00, 0x7f, 0xff][at % 3];
            let mut damaged = good.clone();
            damaged[at] = byte;
            std::fs::write(&table, &damaged).unwrap();
            match std::panic::catch_unwind(|| CageLoadExport::read(&table)) {
                Ok(Ok(_)) => {}
                Ok(Err(e)) => assert!(e.contains("loads"), "byte {at} = {byte:#x}: {e}"),
                Err(_) => panic!("byte {at} = {byte:#x}: the reader panicked"),
            }
        }
    }
}
