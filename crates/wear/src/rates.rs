//! Wear on every wear line of every surface: a depth (m) or a rate (m/s of depth) — one
//! container for both, since a period's depth is its rate times the period.

use crate::surface::{PerSurface, Surface};

/// What the averaged method works from, per contact kind (seed 000 eqs. 2.36, 2.37), reported
/// for both methods.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactDiagnostics {
    /// equivalent force Q_e (seed 000 eq. 2.36), N
    pub equivalent_force_n: f64,
    /// mean sliding speed while in contact (eq. 2.37), m/s
    pub mean_sliding_speed_m_s: f64,
    /// fraction of the recorded time the contact of a roller is loaded (mean over the rollers)
    pub contact_fraction: f64,
    /// geometric mean Λ over the film-friction contact time
    pub mean_lambda: f64,
    /// fraction of the contact time in boundary friction
    pub boundary_fraction: f64,
}

impl ContactDiagnostics {
    /// Names of [`ContactDiagnostics::values`], for table columns.
    pub const NAMES: [&str; 5] = [
        "equivalent_force_n",
        "mean_sliding_speed_m_s",
        "contact_fraction",
        "mean_lambda",
        "boundary_fraction",
    ];

    /// The fields in the order of [`ContactDiagnostics::NAMES`].
    pub fn values(&self) -> [f64; 5] {
        [
            self.equivalent_force_n,
            self.mean_sliding_speed_m_s,
            self.contact_fraction,
            self.mean_lambda,
            self.boundary_fraction,
        ]
    }
}

impl serde::Serialize for ContactDiagnostics {
    /// The fields by name; a value that is not finite follows docs/outputs.md (`null` and a
    /// reason under `"non_finite"`). A binary format (a stored run state) gets the
    /// [`ContactDiagnostics::values`] as they are.
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        if !serializer.is_human_readable() {
            return self.values().serialize(serializer);
        }
        let values = [
            ("equivalent_force_n", self.equivalent_force_n),
            ("mean_sliding_speed_m_s", self.mean_sliding_speed_m_s),
            ("contact_fraction", self.contact_fraction),
            ("mean_lambda", self.mean_lambda),
            ("boundary_fraction", self.boundary_fraction),
        ];
        let mut object: serde_json::Map<String, serde_json::Value> = values
            .iter()
            .filter(|(_, v)| v.is_finite())
            .map(|&(k, v)| (k.to_string(), v.into()))
            .collect();
        rolldyn_output::mark_non_finite(&mut object, &values, |key, v| match key {
            "mean_lambda" if v.is_nan() => {
                "no contact time in film friction (boundary throughout or no contact)".into()
            }
            _ if v.is_nan() => "no contact in the recorded revolutions".into(),
            _ => rolldyn_output::default_reason(v).into(),
        });
        object.serialize(serializer)
    }
}

impl<'de> serde::Deserialize<'de> for ContactDiagnostics {
    /// The binary form of [`serde::Serialize`]: the [`ContactDiagnostics::values`].
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let [
            equivalent_force_n,
            mean_sliding_speed_m_s,
            contact_fraction,
            mean_lambda,
            boundary_fraction,
        ] = <[f64; 5]>::deserialize(deserializer)?;
        Ok(Self {
            equivalent_force_n,
            mean_sliding_speed_m_s,
            contact_fraction,
            mean_lambda,
            boundary_fraction,
        })
    }
}

/// The contact kinds of [`ContactDiagnostics`], in order.
pub const CONTACT_KINDS: [&str; 4] = ["inner_raceway", "outer_raceway", "cage_bar", "rib"];

/// Wear on the wear lines: the roller and bar lines are the roller's slice centres; the
/// raceway maps are lines × angular bins (line-major); the roller end and the rib carry one
/// line each.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct SurfaceWear {
    pub lines: usize,
    pub bins: usize,
    pub roller_count: usize,
    /// roller, worn by the raceways (mean over the rollers)
    pub roller: Vec<f64>,
    /// roller, worn by the cage bar (mean over the rollers)
    pub roller_at_bar: Vec<f64>,
    pub inner_map: Vec<f64>,
    pub outer_map: Vec<f64>,
    /// bar face of every pocket (pocket-major)
    pub bar_by_pocket: Vec<f64>,
    pub roller_end: f64,
    pub rib: f64,
    pub diagnostics: [ContactDiagnostics; 4],
    /// recorded time the rates come from, s (0 for depths)
    pub recorded_s: f64,
}

impl SurfaceWear {
    pub fn zero(lines: usize, bins: usize, roller_count: usize) -> Self {
        Self {
            lines,
            bins,
            roller_count,
            roller: vec![0.0; lines],
            roller_at_bar: vec![0.0; lines],
            inner_map: vec![0.0; lines * bins],
            outer_map: vec![0.0; lines * bins],
            bar_by_pocket: vec![0.0; lines * roller_count],
            ..Self::default()
        }
    }

    /// Every line value times `f` (diagnostics kept).
    pub fn scaled(&self, f: f64) -> Self {
        let s = |v: &Vec<f64>| v.iter().map(|x| x * f).collect();
        Self {
            roller: s(&self.roller),
            roller_at_bar: s(&self.roller_at_bar),
            inner_map: s(&self.inner_map),
            outer_map: s(&self.outer_map),
            bar_by_pocket: s(&self.bar_by_pocket),
            roller_end: self.roller_end * f,
            rib: self.rib * f,
            ..self.clone()
        }
    }

    /// `self += other × f` (a period's depth: the rates times the period).
    pub fn add_scaled(&mut self, other: &Self, f: f64) {
        let add =
            |a: &mut Vec<f64>, b: &Vec<f64>| a.iter_mut().zip(b).for_each(|(x, y)| *x += y * f);
        add(&mut self.roller, &other.roller);
        add(&mut self.roller_at_bar, &other.roller_at_bar);
        add(&mut self.inner_map, &other.inner_map);
        add(&mut self.outer_map, &other.outer_map);
        add(&mut self.bar_by_pocket, &other.bar_by_pocket);
        self.roller_end += other.roller_end * f;
        self.rib += other.rib * f;
    }

    /// Roller wear on each line from all its contacts.
    pub fn roller_total(&self) -> Vec<f64> {
        self.roller
            .iter()
            .zip(&self.roller_at_bar)
            .map(|(a, b)| a + b)
            .collect()
    }

    /// Bar wear on each line, mean over the pockets.
    pub fn bar_mean(&self) -> Vec<f64> {
        (0..self.lines)
            .map(|s| {
                (0..self.roller_count)
                    .map(|j| self.bar_by_pocket[j * self.lines + s])
                    .sum::<f64>()
                    / self.roller_count as f64
            })
            .collect()
    }

    /// Circumferential mean of a raceway map on each line.
    pub fn map_mean(map: &[f64], bins: usize) -> Vec<f64> {
        map.chunks(bins)
            .map(|c| c.iter().sum::<f64>() / bins as f64)
            .collect()
    }

    /// Largest value on the surface.
    pub fn max(&self, surface: Surface) -> f64 {
        let max = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
        match surface {
            Surface::Roller => max(&self.roller_total()),
            Surface::InnerRaceway => max(&self.inner_map),
            Surface::OuterRaceway => max(&self.outer_map),
            Surface::CageBar => max(&self.bar_mean()),
            Surface::RollerEnd => self.roller_end,
            Surface::Rib => self.rib,
        }
    }

    pub fn max_per_surface(&self) -> PerSurface<f64> {
        PerSurface::from_fn(|s| self.max(s))
    }

    /// Increase of the operating radial (diametral) clearance G_r = D_o − d_i − 2 D_w from the
    /// deepest wear of each part: 2 h_i + 2 h_o + 4 h_roller (each roller diameter shrinks by
    /// 2 h on the two raceways' sides).
    pub fn clearance_increase(&self) -> f64 {
        2.0 * self.max(Surface::InnerRaceway)
            + 2.0 * self.max(Surface::OuterRaceway)
            + 4.0 * self.max(Surface::Roller)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rolldyn_output::run_state::{StateFile, fingerprint};

    /// A stored run state keeps every value: the diagnostics whose JSON drops what is not
    /// finite, and the per-surface maps.
    #[test]
    fn a_stored_wear_state_reads_back_bit_for_bit() {
        let mut wear = SurfaceWear::zero(2, 3, 4);
        wear.roller[1] = 0.1 + 0.2;
        wear.diagnostics[2] = ContactDiagnostics {
            equivalent_force_n: 12.5,
            mean_sliding_speed_m_s: f64::INFINITY,
            contact_fraction: -0.0,
            mean_lambda: f64::NAN,
            boundary_fraction: 5e-324,
        };
        let depths = PerSurface::from_fn(|s| s as usize as f64 * 1e-7);
        let dir = std::env::temp_dir().join(format!("rolldyn-wear-state-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = StateFile::new(dir.join("wear.state"), fingerprint("test"));
        file.store(&(&wear, depths)).unwrap();
        let (back, back_depths): (SurfaceWear, PerSurface<f64>) = file.load().unwrap().unwrap();
        let bits = |d: &ContactDiagnostics| d.values().map(f64::to_bits);
        for (a, b) in wear.diagnostics.iter().zip(&back.diagnostics) {
            assert_eq!(bits(a), bits(b));
        }
        assert_eq!(back.roller, wear.roller);
        assert_eq!(back_depths, depths);
        std::fs::remove_dir_all(dir).unwrap();
    }
}
