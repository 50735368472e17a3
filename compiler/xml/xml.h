/* xml.h — importing SoliDualSPHysics case files (Case_Def.xml).
 *
 * The importer reads the XML with libxml2 and appends to a Program the same items the
 * parser builds for the equivalent .sph model (imports of the material laws, the scene,
 * `let`s, bodies with their boundary conditions and measurement planes), so the rest of
 * the compiler does not know where a model came from.  docs/xml.md describes what is
 * supported and how GenCase geometry becomes sph shapes. */
#ifndef SPHC_XML_H
#define SPHC_XML_H

#include "front/ast.h"

/* How the importer reads what SoliDualSPHysics and sphc read differently (docs/xml.md). */
typedef struct {
    /* 2D cases: elastic constants as SoliDualSPHysics reads them, the constants of
     * two-dimensional elasticity (u_bulk = lambda + mu; youngmod and poissratio the plane
     * strain E/(1 - nu^2) and nu/(1 - nu)), instead of the 3D constants (sphc --xml-elastic2d). */
    int elastic2d_sdsph;
    /* Particles where GenCase puts them (sphc --xml-fill=gencase) instead of cell centres
     * inside the drawn shapes, which keep their true volume (docs/xml.md). */
    int fill_gencase;
} XmlOptions;

/* Import the case file at path into prog.  Returns the number of errors reported
 * (0 on success); messages go to stderr as "file:line: error: <element>: ...". */
int xml_import(const char *path, const XmlOptions *opt, Program *prog);

/* Whether path names an XML case file (it ends in ".xml", any case). */
int xml_is_case_file(const char *path);

#endif
