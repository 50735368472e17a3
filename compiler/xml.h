/* xml.h — importing SoliDualSPHysics case files (Case_Def.xml).
 *
 * The importer reads the XML with libxml2 and appends to a Program the same items the
 * parser builds for the equivalent .sph model (imports of the material laws, the scene,
 * `let`s, bodies with their boundary conditions and measurement planes), so the rest of
 * the compiler does not know where a model came from.  docs/xml.md describes what is
 * supported and how GenCase geometry becomes sph shapes. */
#ifndef SPHC_XML_H
#define SPHC_XML_H

#include "ast.h"

/* Import the case file at path into prog.  Returns the number of errors reported
 * (0 on success); messages go to stderr as "file:line: error: <element>: ...". */
int xml_import(const char *path, Program *prog);

/* Whether path names an XML case file (it ends in ".xml", any case). */
int xml_is_case_file(const char *path);

#endif
