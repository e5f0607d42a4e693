#pragma once
/// \file CObjectMapCreationOptions.h
/// The keys of `[<prefix>_creationOpts]` of a semanticObjectMap (map_file, class_names), declared once:
/// loading, the dump and doc/object-map.md's key table derive from it (MRPT's common keys of the
/// section, enableSaveAs3DObject ..., are read by MRPT itself).

#include <simp/io/OptionTable.h>
#include <simp/maps/CObjectMap.h>

namespace simp::maps {

const io::OptionTable<CObjectMap::TMapDefinition>& creationOptionsTable();

}  // namespace simp::maps
