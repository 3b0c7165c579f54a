//! The type of each field of a planner struct, read from its `Serialize` implementation:
//! a serializer that records what it is asked to write (the type's name, or the names of a
//! struct's fields) instead of writing it, so the registry never lists a field or a type
//! by hand.

use std::fmt;

use serde::ser::{self, Serialize};

/// A serialized value's type: its name and, for a struct, its fields.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Ty {
    /// `f64`, `bool`, `Option<f64>`, `Option` (a `None`: its inner type is not written),
    /// or an enum's or a struct's name.
    pub name: String,
    /// The fields, for a struct.
    pub fields: Vec<(&'static str, Ty)>,
}

impl Ty {
    fn named(name: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            fields: Vec::new(),
        }
    }
}

/// The type of `value` as its `Serialize` implementation describes it.
pub(crate) fn type_of<T: Serialize + ?Sized>(value: &T) -> Ty {
    // The recorder never fails: every method answers a type.
    value.serialize(Recorder).unwrap_or_else(|_| Ty::named("?"))
}

/// The serializer that records types.
struct Recorder;

/// A compound value being recorded: its name and the fields seen so far.
struct Compound(Ty);

macro_rules! primitive {
    ($($method:ident: $t:ty),* $(,)?) => {
        $(fn $method(self, _: $t) -> Result<Ty, fmt::Error> {
            Ok(Ty::named(stringify!($t)))
        })*
    };
}

/// Tuple structs, structs and their enum-variant forms are named by their type's name
/// (the arguments after the name are their lengths and variant tags, not needed here).
macro_rules! named_compounds {
    ($($method:ident($($arg:ty),*)),* $(,)?) => {
        $(fn $method(self, name: &'static str, $(_: $arg),*) -> Result<Compound, fmt::Error> {
            Ok(Compound(Ty::named(name)))
        })*
    };
}

impl ser::Serializer for Recorder {
    type Ok = Ty;
    type Error = fmt::Error;
    type SerializeSeq = Compound;
    type SerializeTuple = Compound;
    type SerializeTupleStruct = Compound;
    type SerializeTupleVariant = Compound;
    type SerializeMap = Compound;
    type SerializeStruct = Compound;
    type SerializeStructVariant = Compound;

    primitive!(
        serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
        serialize_u64: u64, serialize_f32: f32, serialize_f64: f64, serialize_char: char,
    );

    fn serialize_str(self, _: &str) -> Result<Ty, fmt::Error> {
        Ok(Ty::named("string"))
    }
    fn serialize_bytes(self, _: &[u8]) -> Result<Ty, fmt::Error> {
        Ok(Ty::named("bytes"))
    }
    fn serialize_none(self) -> Result<Ty, fmt::Error> {
        Ok(Ty::named("Option"))
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<Ty, fmt::Error> {
        Ok(Ty::named(format!("Option<{}>", type_of(value).name)))
    }
    fn serialize_unit(self) -> Result<Ty, fmt::Error> {
        Ok(Ty::named("()"))
    }
    fn serialize_unit_struct(self, name: &'static str) -> Result<Ty, fmt::Error> {
        Ok(Ty::named(name))
    }
    fn serialize_unit_variant(
        self,
        name: &'static str,
        _: u32,
        _: &'static str,
    ) -> Result<Ty, fmt::Error> {
        Ok(Ty::named(name))
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        name: &'static str,
        _: &T,
    ) -> Result<Ty, fmt::Error> {
        Ok(Ty::named(name))
    }
    /// A variant holding a value is the value's type: `PlannerConfig::Rrt(rrt)` is `Rrt`'s
    /// struct with its fields, `RewireRadius::Gamma(40.0)` names its enum.
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        name: &'static str,
        _: u32,
        _: &'static str,
        value: &T,
    ) -> Result<Ty, fmt::Error> {
        let inner = type_of(value);
        Ok(if inner.fields.is_empty() {
            Ty::named(name)
        } else {
            inner
        })
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound, fmt::Error> {
        Ok(Compound(Ty::named("list")))
    }
    fn serialize_tuple(self, _: usize) -> Result<Compound, fmt::Error> {
        Ok(Compound(Ty::named("tuple")))
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Compound, fmt::Error> {
        Ok(Compound(Ty::named("map")))
    }
    named_compounds!(
        serialize_tuple_struct(usize),
        serialize_tuple_variant(u32, &'static str, usize),
        serialize_struct(usize),
        serialize_struct_variant(u32, &'static str, usize),
    );
}

/// Elements of lists, tuples and maps are not recorded: the compound's name is its type.
macro_rules! elements_ignored {
    ($($trait:ident: $method:ident),* $(,)?) => {
        $(impl ser::$trait for Compound {
            type Ok = Ty;
            type Error = fmt::Error;
            fn $method<T: Serialize + ?Sized>(&mut self, _: &T) -> Result<(), fmt::Error> {
                Ok(())
            }
            fn end(self) -> Result<Ty, fmt::Error> {
                Ok(self.0)
            }
        })*
    };
}

elements_ignored!(
    SerializeSeq: serialize_element,
    SerializeTuple: serialize_element,
    SerializeTupleStruct: serialize_field,
    SerializeTupleVariant: serialize_field,
);

impl ser::SerializeMap for Compound {
    type Ok = Ty;
    type Error = fmt::Error;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, _: &T) -> Result<(), fmt::Error> {
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, _: &T) -> Result<(), fmt::Error> {
        Ok(())
    }
    fn end(self) -> Result<Ty, fmt::Error> {
        Ok(self.0)
    }
}

/// A struct's fields (of a plain struct or an enum's struct variant) are recorded with
/// their types.
macro_rules! fields_recorded {
    ($($trait:ident),* $(,)?) => {
        $(impl ser::$trait for Compound {
            type Ok = Ty;
            type Error = fmt::Error;
            fn serialize_field<T: Serialize + ?Sized>(
                &mut self,
                key: &'static str,
                value: &T,
            ) -> Result<(), fmt::Error> {
                self.0.fields.push((key, type_of(value)));
                Ok(())
            }
            fn end(self) -> Result<Ty, fmt::Error> {
                Ok(self.0)
            }
        })*
    };
}

fields_recorded!(SerializeStruct, SerializeStructVariant);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_planner_struct_reads_as_its_fields() {
        let t = type_of(&sampling::RrtStar::default());
        let names: Vec<(&str, &str)> = t
            .fields
            .iter()
            .map(|(k, t)| (*k, t.name.as_str()))
            .collect();
        assert!(names.contains(&("step", "f64")), "{names:?}");
        assert!(
            names.contains(&("stop_at_first_solution", "bool")),
            "{names:?}"
        );
        assert!(names.contains(&("rewire", "RewireRadius")), "{names:?}");
        let budget = &t.fields.iter().find(|(k, _)| *k == "budget").unwrap().1;
        assert_eq!(budget.name, "Budget");
        assert_eq!(budget.fields.len(), 2);
    }
}
