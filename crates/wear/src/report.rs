//! The tables and plots of a life run (`rolldyn wear --out DIR`, docs/outputs.md "wear"):
//! streamed period by period so that a run stopped by a failure keeps what it computed.

use crate::life::PeriodRecord;
use crate::rates::{ContactDiagnostics, SurfaceWear};
use crate::surface::Surface;
use rolldyn_geometry::angle_bin_centre_rad;
use rolldyn_output::{Formats, KeptRows, OutputError, TableWriter};
use rolldyn_plot::{Field, Labels, MapLabels, PlotError, Series, line_plot, map_plot};
use std::path::{Path, PathBuf};

/// µm per m
pub(crate) const UM: f64 = 1e6;
/// rates are reported in µm per 1000 h
pub(crate) const UM_PER_KH: f64 = 1e6 * 3.6e6;

/// Column names of the periods table.
pub fn period_columns() -> Vec<String> {
    let mut names: Vec<String> = [
        "period",
        "time_h",
        "period_h",
        "cage_speed_rad_s",
        "revolutions",
        "clearance_increase_um",
        "halvings",
        "dynamics_wall_s",
        "wear_wall_s",
    ]
    .map(String::from)
    .into();
    for s in Surface::ALL {
        names.push(format!("max_depth_{}_um", s.name()));
        names.push(format!("max_rate_{}_um_per_1000h", s.name()));
    }
    for (kind, _) in crate::rates::CONTACT_KINDS.iter().zip(0..) {
        for q in ContactDiagnostics::NAMES {
            names.push(format!("{kind}_{q}"));
        }
    }
    names
}

fn period_row(p: &PeriodRecord) -> Vec<f64> {
    let mut row = vec![
        p.index as f64,
        p.time_h,
        p.period_h,
        p.cage_speed_rad_s,
        p.revolutions,
        p.clearance_increase_m * UM,
        p.halvings as f64,
        p.dynamics_wall_s,
        p.wear_wall_s,
    ];
    for s in Surface::ALL {
        row.push(p.max_depth_m.get(s) * UM);
        row.push(p.max_rate_m_s.get(s) * UM_PER_KH);
    }
    for c in &p.contacts {
        row.extend(c.values());
    }
    row
}

fn names(n: &[&str]) -> Vec<String> {
    n.iter().map(|s| s.to_string()).collect()
}

/// The roller and bar depth profiles at the end of one period.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
struct ProfileHistory {
    time_h: f64,
    roller: Vec<f64>,
    bar: Vec<f64>,
}

/// What the stored state of a life run notes of its tables: the rows of each table
/// (periods, roller and bar profiles, inner and outer raceway maps) and the profile histories
/// of the plots, after the last stored period.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub struct WearTablesNote {
    kept: [KeptRows; 5],
    history: Vec<ProfileHistory>,
}

/// The tables of a life run, written as the periods come.
pub struct WearTables {
    dir: PathBuf,
    periods: TableWriter,
    roller: TableWriter,
    bar: TableWriter,
    maps: [TableWriter; 2],
    /// roller and bar depths per period, for the plots
    history: Vec<ProfileHistory>,
    records: Vec<PeriodRecord>,
    positions_mm: Vec<f64>,
}

impl WearTables {
    pub fn create(dir: &Path, positions_m: &[f64]) -> Result<Self, OutputError> {
        Self::open(dir, positions_m, None, &[])
    }

    /// Continues the tables of an interrupted run in `dir` after its `records` (the periods
    /// of its stored state) and the rows its `note` kept; later rows are dropped and the
    /// Parquet files rebuilt ([`TableWriter::resume`]).
    pub fn resume(
        dir: &Path,
        positions_m: &[f64],
        note: &WearTablesNote,
        records: &[PeriodRecord],
    ) -> Result<Self, OutputError> {
        Self::open(dir, positions_m, Some(note), records)
    }

    fn open(
        dir: &Path,
        positions_m: &[f64],
        note: Option<&WearTablesNote>,
        records: &[PeriodRecord],
    ) -> Result<Self, OutputError> {
        let fresh = KeptRows { rows: 0, digest: 0 };
        let [periods, roller, bar, inner, outer] = note.map_or([fresh; 5], |n| n.kept);
        let table = |stem: &str, names: &[String], kept: KeptRows| {
            TableWriter::resume(dir, stem, names, Formats::default(), kept, |_| {})
        };
        let profile = names(&["period", "time_h", "x_mm", "depth_um", "depth_from_bar_um"]);
        let bar_columns = names(&[
            "period",
            "time_h",
            "x_mm",
            "depth_mean_um",
            "depth_max_pocket_um",
        ]);
        let map = names(&["period", "time_h", "axial_mm", "angle_deg", "depth_um"]);
        Ok(Self {
            dir: dir.to_path_buf(),
            periods: table("periods", &period_columns(), periods)?,
            roller: table("roller-profile", &profile, roller)?,
            bar: table("bar-profile", &bar_columns, bar)?,
            maps: [
                table("inner-raceway-map", &map, inner)?,
                table("outer-raceway-map", &map, outer)?,
            ],
            history: note.map_or_else(Vec::new, |n| n.history.clone()),
            records: records.to_vec(),
            positions_mm: positions_m.iter().map(|x| x * 1e3).collect(),
        })
    }

    /// The rows written so far and the plots' histories, for the stored state.
    pub fn note(&self) -> WearTablesNote {
        let [inner, outer] = &self.maps;
        WearTablesNote {
            kept: [&self.periods, &self.roller, &self.bar, inner, outer].map(TableWriter::kept),
            history: self.history.clone(),
        }
    }

    /// Writes one period's rows and hands them to the system (a stored state never runs
    /// ahead of the tables).
    pub fn period(&mut self, p: &PeriodRecord, depth: &SurfaceWear) -> Result<(), OutputError> {
        self.periods.write_row(&period_row(p))?;
        let (i, t) = (p.index as f64, p.time_h);
        let roller = depth.roller_total();
        let bar_mean = depth.bar_mean();
        for (s, &x) in self.positions_mm.iter().enumerate() {
            self.roller
                .write_row(&[i, t, x, roller[s] * UM, depth.roller_at_bar[s] * UM])?;
            let pockets = (0..depth.roller_count).map(|j| depth.bar_by_pocket[j * depth.lines + s]);
            let bar_max = pockets.fold(0.0, f64::max);
            self.bar
                .write_row(&[i, t, x, bar_mean[s] * UM, bar_max * UM])?;
        }
        for (table, map) in self
            .maps
            .iter_mut()
            .zip([&depth.inner_map, &depth.outer_map])
        {
            for (s, &x) in self.positions_mm.iter().enumerate() {
                for b in 0..depth.bins {
                    let angle = angle_bin_centre_rad(b, depth.bins).to_degrees();
                    table.write_row(&[i, t, x, angle, map[s * depth.bins + b] * UM])?;
                }
            }
        }
        let [inner, outer] = &mut self.maps;
        for t in [
            &mut self.periods,
            &mut self.roller,
            &mut self.bar,
            inner,
            outer,
        ] {
            t.flush()?;
        }
        self.history.push(ProfileHistory {
            time_h: t,
            roller,
            bar: bar_mean,
        });
        self.records.push(p.clone());
        Ok(())
    }

    /// Closes the tables and draws the plots of the run (the final raceway map from `depth`).
    pub fn finish(self, depth: &SurfaceWear) -> Result<Vec<PathBuf>, WearReportError> {
        let Self {
            dir,
            periods,
            roller,
            bar,
            maps,
            history,
            records,
            positions_mm,
        } = self;
        for t in [periods, roller, bar].into_iter().chain(maps) {
            t.finish()?;
        }
        let mut written = Vec::new();
        let profile_plot =
            |name: &str, title: &str, pick: &dyn Fn(&ProfileHistory) -> &Vec<f64>| {
                let curves: Vec<(String, Vec<(f64, f64)>)> = history
                    .iter()
                    .map(|h| {
                        let pts = positions_mm
                            .iter()
                            .zip(pick(h))
                            .map(|(&x, &d)| (x, d * UM))
                            .collect();
                        (format!("{:.0} h", h.time_h), pts)
                    })
                    .collect();
                let path = dir.join(name);
                line_plot(
                    &path,
                    &Labels {
                        title,
                        x: "axial position, mm",
                        y: "wear depth, µm",
                    },
                    &Series::from_pairs(&curves),
                )
                .map(|_| path)
            };
        written.push(profile_plot(
            "roller-profile.svg",
            "Roller wear along the roller, per period",
            &|h| &h.roller,
        )?);
        written.push(profile_plot(
            "bar-profile.svg",
            "Cage-bar wear along the bar (mean over pockets)",
            &|h| &h.bar,
        )?);
        let rates: Vec<(String, Vec<(f64, f64)>)> = Surface::ALL
            .iter()
            .map(|&s| {
                let pts = records
                    .iter()
                    .map(|p| (p.time_h, p.max_rate_m_s.get(s) * UM_PER_KH))
                    .collect();
                (s.name().to_string(), pts)
            })
            .collect();
        let path = dir.join("rates.svg");
        line_plot(
            &path,
            &Labels {
                title: "Largest wear rate per period",
                x: "operating time, h",
                y: "rate, µm per 1000 h",
            },
            &Series::from_pairs(&rates),
        )?;
        written.push(path);
        for (name, title, map) in [
            (
                "inner-raceway-map.svg",
                "Inner-raceway wear depth at the end (ring frame)",
                &depth.inner_map,
            ),
            (
                "outer-raceway-map.svg",
                "Outer-raceway wear depth at the end (ring frame)",
                &depth.outer_map,
            ),
        ] {
            // heat_map stores x fastest: angle along x, axial line along y
            let values: Vec<f64> = map.iter().map(|d| d * UM).collect();
            let (x0, x1) = (positions_mm[0], positions_mm[positions_mm.len() - 1]);
            let path = dir.join(name);
            map_plot(
                &path,
                &Labels {
                    title,
                    x: "angle, deg",
                    y: "axial position, mm",
                },
                &Field {
                    values: &values,
                    nx: depth.bins,
                    ny: depth.lines,
                    extent: (0.0, 360.0, x0, x1),
                },
                &MapLabels {
                    value: "wear depth, µm",
                    outline: &[],
                },
            )?;
            written.push(path);
        }
        Ok(written)
    }
}

/// A table or plot that could not be written.
#[derive(Debug, thiserror::Error)]
pub enum WearReportError {
    #[error("{0}")]
    Table(#[from] OutputError),
    #[error("{0}")]
    Plot(#[from] PlotError),
}
