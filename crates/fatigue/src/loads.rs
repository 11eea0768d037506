//! The cage-load export (SPEC §7.2, docs/outputs.md "Cage loads"): one steady cage revolution
//! as 180 load sets (2° of cage rotation apart), each with every contact force on the cage and
//! its point of application in cage coordinates ([`crate::cage`]), and the cage's rigid-body
//! motion. Written as a Parquet table of contact rows plus a small JSON header, SI units, so a
//! user's own finite-element model can read it too.

use crate::cage::CageGeometry;
use crate::cage_material::CageMaterial;
use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::Field;
use rolldyn_output::mixed_table::{Column, Values, write_parquet_table};
use serde::{Deserialize, Serialize};
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
        for (set, contact) in read_contacts(table)? {
            let sets = export.sets.len();
            let target = export.sets.get_mut(set).ok_or_else(|| {
                format!("{}: set {set} beyond the header's {sets}", table.display())
            })?;
            target.contacts.push(contact);
        }
        Ok(export)
    }
}

/// The contact rows of a load table: (set, contact).
fn read_contacts(table: &Path) -> Result<Vec<(usize, ContactLoad)>, String> {
    let fail = |e: &dyn std::fmt::Display| format!("{}: {e}", table.display());
    let file = std::fs::File::open(table).map_err(|e| fail(&e))?;
    let reader = SerializedFileReader::new(file).map_err(|e| fail(&e))?;
    let rows = reader.get_row_iter(None).map_err(|e| fail(&e))?;
    let mut out = Vec::new();
    for row in rows {
        let row = row.map_err(|e| fail(&e))?;
        let mut kind = None;
        let mut v = [f64::NAN; 9];
        for (name, field) in row.get_column_iter() {
            match (name.as_str(), field) {
                ("kind", Field::Str(s)) => kind = ContactKind::parse(s),
                (n, Field::Double(x)) => {
                    let names = [
                        "set", "pocket", "location", "fx_n", "fy_n", "fz_n", "x_m", "y_m", "z_m",
                    ];
                    if let Some(i) = names.iter().position(|&m| m == n) {
                        v[i] = *x;
                    }
                }
                _ => {}
            }
        }
        let kind = kind.ok_or_else(|| fail(&"a row without a known contact kind"))?;
        if v.iter().any(|x| !x.is_finite()) {
            return Err(fail(&"a row with a missing number"));
        }
        if v[..3].iter().any(|x| *x < 0.0 || x.fract() != 0.0) {
            return Err(fail(&"set, pocket and location must be whole numbers ≥ 0"));
        }
        out.push((
            v[0] as usize,
            ContactLoad {
                kind,
                pocket: v[1] as usize,
                location: v[2] as usize,
                force_n: [v[3], v[4], v[5]],
                point_m: [v[6], v[7], v[8]],
            },
        ));
    }
    Ok(out)
}

/// The largest contact forces of the recorded revolution (seed 000 Table 3.2 columns the
/// correlations of V-27 use), N.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RevolutionMaxima {
    pub max_cage_land_force_n: f64,
    pub max_roller_cage_force_n: f64,
    pub max_roller_raceway_force_n: f64,
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

    #[test]
    fn an_export_reads_back_as_written() {
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
        let export = CageLoadExport {
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
        };
        let dir = std::env::temp_dir().join(format!("rolldyn-loads-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("loads.parquet");
        export.write(&path).unwrap();
        assert_eq!(CageLoadExport::read(&path).unwrap(), export);
    }
}
