#pragma once

namespace featloc
{
/** Registers every featloc RTTI class (the scan matchers) and the MRPT
 * modules featloc reads and writes (obs, maps, poses, opengl), so that
 * classFactory() finds the matchers and rawlogs deserialize.
 *
 * Call it once at start-up from every program and test: featloc is a static
 * library, and MRPT's static initializers in it would be dropped at link
 * time; Debian's --as-needed linking can likewise drop MRPT modules whose
 * symbols a program never names. Safe to call more than once. */
void registerClasses();
}  // namespace featloc
