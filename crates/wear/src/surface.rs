//! The worn surfaces of a cylindrical roller bearing.

use serde::Serialize;

/// A surface whose wear rolldyn tracks (seed 000 §3.1.1.5–3.1.1.7).
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum Surface {
    /// the roller's rolling surface (worn by both raceways and the cage bar)
    Roller,
    InnerRaceway,
    OuterRaceway,
    /// the cage bar face the roller pushes on
    CageBar,
    /// the roller end face at the rib contact
    RollerEnd,
    /// the rib face at the roller-end contact
    Rib,
}

impl Surface {
    pub const ALL: [Surface; 6] = [
        Surface::Roller,
        Surface::InnerRaceway,
        Surface::OuterRaceway,
        Surface::CageBar,
        Surface::RollerEnd,
        Surface::Rib,
    ];

    /// The name used in JSON keys, table columns and file names.
    pub fn name(self) -> &'static str {
        match self {
            Surface::Roller => "roller",
            Surface::InnerRaceway => "inner_raceway",
            Surface::OuterRaceway => "outer_raceway",
            Surface::CageBar => "cage_bar",
            Surface::RollerEnd => "roller_end",
            Surface::Rib => "rib",
        }
    }
}

/// One value per surface, addressed by name.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PerSurface<T> {
    values: [T; 6],
}

impl<T: Copy> PerSurface<T> {
    pub fn from_fn(mut f: impl FnMut(Surface) -> T) -> Self {
        Self {
            values: Surface::ALL.map(&mut f),
        }
    }

    pub fn get(&self, s: Surface) -> T {
        self.values[s as usize]
    }

    pub fn set(&mut self, s: Surface, v: T) {
        self.values[s as usize] = v;
    }

    pub fn iter(&self) -> impl Iterator<Item = (Surface, T)> + '_ {
        Surface::ALL.iter().map(|&s| (s, self.get(s)))
    }
}

impl<T: Copy + Serialize> Serialize for PerSurface<T> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = serializer.serialize_map(Some(6))?;
        for (s, v) in self.iter() {
            map.serialize_entry(s.name(), &v)?;
        }
        map.end()
    }
}

impl<'de, T: Copy + serde::Deserialize<'de>> serde::Deserialize<'de> for PerSurface<T> {
    /// The map [`Serialize`] writes: one value under each surface's name.
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let map = std::collections::BTreeMap::<Surface, T>::deserialize(deserializer)?;
        let value = |s: Surface| {
            map.get(&s)
                .copied()
                .ok_or_else(|| serde::de::Error::custom(format!("no value of {}", s.name())))
        };
        let values: Vec<T> = Surface::ALL
            .into_iter()
            .map(value)
            .collect::<Result<_, _>>()?;
        Ok(Self {
            values: values.try_into().ok().expect("one value per surface"),
        })
    }
}
