//! Where a cylindrical run's samples go: the `out` tables (CSV + Parquet, continued after a
//! resume) with the decimated histories of their plots, tables kept in memory, and the
//! cage-load recorder.

use crate::failure::Failure;
use rolldyn_dynamics::output::{OutputSink, RevolutionSummary, Snapshot};
use rolldyn_dynamics::output_columns::{
    BEARING_COLUMNS, Column, MemoryTables, REVOLUTION_COLUMNS, ROLLER_COLUMNS, bearing_row,
    column_names, revolution_row, roller_row,
};
use rolldyn_fatigue::CageLoadRecorder;
use rolldyn_output::{Formats, KeptRows, OutputError, TableWriter};
use rolldyn_plot::{ClearanceCircle, Labels, Series, line_plot, orbit_plot};
use std::path::Path;

/// Keeps at most `capacity` points of a history for plotting (halving the density when full),
/// so that memory stays bounded however long the run.
struct Decimated {
    points: Vec<(f64, f64)>,
    stride: usize,
    seen: usize,
    capacity: usize,
}

impl Decimated {
    fn new(capacity: usize) -> Self {
        Self {
            points: Vec::new(),
            stride: 1,
            seen: 0,
            capacity,
        }
    }

    fn push(&mut self, x: f64, y: f64) {
        if self.seen.is_multiple_of(self.stride) {
            if self.points.len() == self.capacity {
                self.points = self.points.iter().step_by(2).copied().collect();
                self.stride *= 2;
            }
            if self.seen.is_multiple_of(self.stride) {
                self.points.push((x, y));
            }
        }
        self.seen += 1;
    }
}

/// The decimated histories of the plots, fed with the table rows (so that a resumed run
/// rebuilds them from the rows it keeps).
struct Plots {
    cage_speed: Decimated,
    epicyclic: Decimated,
    cage_slip: Decimated,
    cage_orbit: Decimated,
    inner_orbit: Decimated,
    roller_inner: Decimated,
    roller_outer: Decimated,
    roller_bar: Decimated,
}

/// Position of the column `name` in a table schema.
fn position<A>(columns: &[Column<A>], name: &str) -> usize {
    columns
        .iter()
        .position(|c| c.name == name)
        .expect("a column of the schema")
}

impl Plots {
    fn new() -> Self {
        let plot = || Decimated::new(4000);
        Self {
            cage_speed: plot(),
            epicyclic: plot(),
            cage_slip: plot(),
            cage_orbit: plot(),
            inner_orbit: plot(),
            roller_inner: plot(),
            roller_outer: plot(),
            roller_bar: plot(),
        }
    }

    /// A row of the `bearing` table.
    fn bearing(&mut self, row: &[f64]) {
        let v = |name| row[position(&BEARING_COLUMNS, name)];
        let t = v("time_s");
        self.cage_speed.push(t, v("cage_speed_rad_s"));
        self.epicyclic.push(t, v("epicyclic_cage_speed_rad_s"));
        self.cage_slip.push(t, v("cage_slip"));
        self.cage_orbit
            .push(v("cage_x_m") * 1e6, v("cage_y_m") * 1e6);
        self.inner_orbit
            .push(v("inner_ring_x_m") * 1e6, v("inner_ring_y_m") * 1e6);
    }

    /// A row of the `rollers` table: the forces of roller 1 are plotted.
    fn roller(&mut self, row: &[f64]) {
        let v = |name| row[position(&ROLLER_COLUMNS, name)];
        if v("roller") == 1.0 {
            let t = v("time_s");
            self.roller_inner.push(t, v("inner_force_n"));
            self.roller_outer.push(t, v("outer_force_n"));
            self.roller_bar.push(t, v("cage_bar_force_n"));
        }
    }
}

/// What a checkpoint notes of the `--out` tables `bearing`, `rollers` and `revolutions`: their
/// rows and digests at that point.
pub type TablesNote = [KeptRows; 3];

pub fn encode_note(note: &TablesNote) -> Vec<u8> {
    note.iter()
        .flat_map(|k| [k.rows as u64, k.digest])
        .flat_map(u64::to_le_bytes)
        .collect()
}

/// The tables note of a checkpoint; `None` when its run had no `--out` (an empty note).
pub fn decode_note(note: &[u8]) -> Result<Option<TablesNote>, String> {
    if note.is_empty() {
        return Ok(None);
    }
    let words: Vec<u64> = note
        .chunks_exact(8)
        .map(|b| u64::from_le_bytes(b.try_into().expect("8 bytes")))
        .collect();
    match words.as_slice() {
        &[r0, d0, r1, d1, r2, d2] if note.len() == 48 => Ok(Some(
            [(r0, d0), (r1, d1), (r2, d2)].map(|(rows, digest)| KeptRows {
                rows: rows as usize,
                digest,
            }),
        )),
        _ => Err("the note on the output tables is not one of rolldyn simulate".into()),
    }
}

/// Streams samples to tables and keeps decimated histories for the plots.
/// The circles the orbit plots draw: the cage's radial gap on its guiding land (none for a
/// cage without one) and the inner ring's radial play, half the diametral clearance G_r.
pub struct OrbitCircles {
    pub cage_land_gap_m: Option<f64>,
    pub ring_play_m: f64,
}

impl OrbitCircles {
    pub fn of(bearing: &rolldyn_geometry::CylindricalRollerBearing) -> Self {
        Self {
            cage_land_gap_m: bearing.cage_guidance_check().map(|c| c.land_radial_gap),
            ring_play_m: 0.5 * bearing.clearance.radial,
        }
    }
}

pub struct FileSink {
    bearing: TableWriter,
    rollers: TableWriter,
    revolutions: TableWriter,
    row: Vec<f64>,
    error: Option<OutputError>,
    plots: Plots,
}

impl FileSink {
    /// The tables in `dir`: new ones, or those of an interrupted run continued after the rows
    /// `kept` by its checkpoint (a `resumed` run; new tables when that run had no `--out`); the
    /// plots start from the kept rows.
    pub fn open(dir: &Path, kept: Option<TablesNote>, resumed: bool) -> Result<Self, Failure> {
        let fresh = KeptRows { rows: 0, digest: 0 };
        let [bearing, rollers, revolutions] = kept.unwrap_or([fresh; 3]);
        let table = |stem: &str, names: Vec<String>, kept, on_row: &mut dyn FnMut(&[f64])| {
            TableWriter::resume(dir, stem, &names, Formats::default(), kept, on_row).map_err(
                |e| match resumed {
                    true => Failure::Input(format!(
                        "{e} (--resume continues the --out folder of the run that wrote the checkpoint)"
                    )),
                    false => Failure::Run(e.to_string()),
                },
            )
        };
        let mut plots = Plots::new();
        Ok(Self {
            bearing: table(
                "bearing",
                column_names(&BEARING_COLUMNS),
                bearing,
                &mut |row| plots.bearing(row),
            )?,
            rollers: table(
                "rollers",
                column_names(&ROLLER_COLUMNS),
                rollers,
                &mut |row| plots.roller(row),
            )?,
            revolutions: table(
                "revolutions",
                column_names(&REVOLUTION_COLUMNS),
                revolutions,
                &mut |_| {},
            )?,
            row: Vec::with_capacity(ROLLER_COLUMNS.len()),
            error: None,
            plots,
        })
    }

    /// The rows written so far, for the checkpoint's note.
    pub fn kept(&self) -> TablesNote {
        [&self.bearing, &self.rollers, &self.revolutions].map(TableWriter::kept)
    }

    fn keep(&mut self, result: Result<(), OutputError>) {
        if let (Err(e), None) = (result, &self.error) {
            self.error = Some(e);
        }
    }

    /// Hands the rows written so far to the system (before a checkpoint, so that the CSV files
    /// are never behind it).
    pub fn flush(&mut self) -> Result<(), OutputError> {
        if let Some(e) = &self.error {
            return Err(e.clone());
        }
        for table in [&mut self.bearing, &mut self.rollers, &mut self.revolutions] {
            table.flush()?;
        }
        Ok(())
    }

    /// Closes the tables and draws the plots; the orbits within `circles`.
    pub fn finish(self, dir: &Path, circles: &OrbitCircles) -> Result<(), Failure> {
        if let Some(e) = self.error {
            return Err(Failure::Run(e.to_string()));
        }
        for table in [self.bearing, self.rollers, self.revolutions] {
            table.finish().map_err(|e| Failure::Run(e.to_string()))?;
        }
        let plot = |file: &str, title: &str, x: &str, y: &str, series: &[Series]| {
            line_plot(&dir.join(file), &Labels { title, x, y }, series)
        };
        plot(
            "cage_speed.svg",
            "Cage speed",
            "time, s",
            "rad/s",
            &[
                Series {
                    label: "cage",
                    points: &self.plots.cage_speed.points,
                },
                Series {
                    label: "epicyclic",
                    points: &self.plots.epicyclic.points,
                },
            ],
        )?;
        plot(
            "cage_slip.svg",
            "Cage slip (1 − ω_c/ω_epicyclic)",
            "time, s",
            "cage slip (fraction)",
            &[Series {
                label: "",
                points: &self.plots.cage_slip.points,
            }],
        )?;
        let orbit =
            |file: &str, title: &str, points: &[(f64, f64)], circle: Option<ClearanceCircle>| {
                let labels = Labels {
                    title,
                    x: "x, µm",
                    y: "y, µm",
                };
                let series = [Series {
                    label: "centre",
                    points,
                }];
                orbit_plot(&dir.join(file), &labels, &series, circle.as_slice())
            };
        orbit(
            "cage_orbit.svg",
            "Cage centre orbit",
            &self.plots.cage_orbit.points,
            circles.cage_land_gap_m.map(|gap| ClearanceCircle {
                label: "land clearance",
                centre: (0.0, 0.0),
                radius: gap * 1e6,
            }),
        )?;
        orbit(
            "inner_ring_orbit.svg",
            "Inner-ring centre orbit",
            &self.plots.inner_orbit.points,
            (circles.ring_play_m > 0.0).then_some(ClearanceCircle {
                label: "radial play G_r/2",
                centre: (0.0, 0.0),
                radius: circles.ring_play_m * 1e6,
            }),
        )?;
        plot(
            "roller_1_forces.svg",
            "Contact forces of roller 1",
            "time, s",
            "force, N",
            &[
                Series {
                    label: "inner raceway",
                    points: &self.plots.roller_inner.points,
                },
                Series {
                    label: "outer raceway",
                    points: &self.plots.roller_outer.points,
                },
                Series {
                    label: "cage bars",
                    points: &self.plots.roller_bar.points,
                },
            ],
        )?;
        Ok(())
    }
}

impl OutputSink for FileSink {
    fn sample(&mut self, _t: f64, s: &Snapshot) {
        bearing_row(s, &mut self.row);
        let result = self.bearing.write_row(&self.row);
        self.keep(result);
        self.plots.bearing(&self.row);
        for j in 0..s.rollers.azimuth_rad.len() {
            roller_row(s, j, &mut self.row);
            let result = self.rollers.write_row(&self.row);
            self.keep(result);
            self.plots.roller(&self.row);
        }
    }

    fn revolution(&mut self, v: &RevolutionSummary) {
        revolution_row(v, &mut self.row);
        let result = self.revolutions.write_row(&self.row);
        self.keep(result);
    }
}

/// Forwards to an optional file sink (so the run is the same with or without `--out`) and
/// tables kept in memory — every `thin`-th sample of the grid `step`, when the cage-load recorder
/// needs a finer grid — and to an optional cage-load recorder.
pub struct Sinks {
    pub files: Option<FileSink>,
    pub loads: Option<CageLoadRecorder>,
    pub memory: Option<MemoryTables>,
    pub step: f64,
    pub thin: u64,
}

impl OutputSink for Sinks {
    fn sample(&mut self, t: f64, s: &Snapshot) {
        if ((t / self.step).round() as u64).is_multiple_of(self.thin) {
            if let Some(f) = &mut self.files {
                f.sample(t, s);
            }
            if let Some(o) = &mut self.memory {
                o.sample(t, s);
            }
        }
        if let Some(r) = &mut self.loads {
            r.sample(t, s);
        }
    }
    fn revolution(&mut self, v: &RevolutionSummary) {
        if let Some(f) = &mut self.files {
            f.revolution(v);
        }
        if let Some(o) = &mut self.memory {
            o.revolution(v);
        }
        if let Some(r) = &mut self.loads {
            r.revolution(v);
        }
    }
}
