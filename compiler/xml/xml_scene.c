/* xml_scene.c — the scene settings of a case: <constantsdef> and <execution><parameters>.
 *
 *   <gravity x y z>           gravity [x, y, z]   (only when not zero)
 *   <coefh value>             coefh               (<hdp value>: coefh = hdp / sqrt(dim))
 *   <cflnumber value>         cfl
 *   StepAlgorithm 1 | 2       integrator verlet | symplectic
 *   Kernel 1 | 2              kernel cubic | wendland
 *   TimeMax, TimeOut          end, output
 *   CoefDtMin                 dtmin
 * The fluid constants and parameters of DualSPHysics are accepted and ignored; others
 * are reported as warnings (they may be misspelt). */
#include <math.h>
#include <string.h>

#include "util/diag.h"
#include "xml_internal.h"

/* The order in which a .sph scene lists its settings. */
static const char *const ORDER[] = {"dimension", "dp",  "kernel", "coefh",  "integrator", "cfl",
                                    "dtmin",     "dt",  "end",    "output", "gravity",    "contact", NULL};

static void set(XmlCtx *x, Setting s)
{
    for (int i = 0; i < x->scene.n; i++)
        if (!strcmp(x->scene.items[i].key, s.key)) {
            x->scene.items[i] = s;
            return;
        }
    ast_push_setting(&x->scene, s);
}

void xml_scene_number(XmlCtx *x, SrcLoc loc, const char *key, double v)
{
    set(x, ast_setting(loc, key, ast_num(loc, v)));
}

void xml_scene_word(XmlCtx *x, SrcLoc loc, const char *key, const char *word)
{
    set(x, ast_setting(loc, key, ast_name(loc, word)));
}

SettingList xml_scene_settings(const XmlCtx *x)
{
    SettingList out = {0};
    for (int k = 0; ORDER[k]; k++)
        for (int i = 0; i < x->scene.n; i++)
            if (!strcmp(x->scene.items[i].key, ORDER[k]))
                ast_push_setting(&out, x->scene.items[i]);
    return out;
}

/* ------------------------------------------------------------------ <constantsdef> */

static int is_fluid_constant(const char *name)
{
    static const char *const fluid[] = {
        "rho0", "rhop0", "hswl", "gamma", "speedsystem", "coefsound", "speedsound", "lattice",
        "b", "massbound", "massfluid", "cs0", "h", "polytropic", NULL};
    for (int i = 0; fluid[i]; i++)
        if (!strcmp(name, fluid[i]))
            return 1;
    return 0;
}

static int gravity(XmlCtx *x, const xmlNode *n)
{
    double g[3];
    if (xml_point(x, n, g))
        return -1;
    if (g[0] == 0 && g[1] == 0 && g[2] == 0)
        return 0;
    SrcLoc loc = xml_loc(x, n);
    Expr **v = NULL;
    int nv = 0;
    for (int k = 0; k < 3; k++)
        ast_push_expr(&v, &nv, ast_num(loc, g[k]));
    set(x, ast_setting(loc, "gravity", ast_vec(loc, v, nv)));
    return 0;
}

static int constant(XmlCtx *x, const xmlNode *n)
{
    double v;
    if (xml_is(n, "gravity"))
        return gravity(x, n);
    if (xml_is(n, "coefh") || xml_is(n, "cflnumber") || xml_is(n, "hdp")) {
        if (xml_card_positive(x, n, &v))
            return -1;
        if (xml_is(n, "hdp"))
            v /= sqrt((double)x->dim);
        xml_scene_number(x, xml_loc(x, n), xml_is(n, "cflnumber") ? "cfl" : "coefh", v);
        return 0;
    }
    if (!is_fluid_constant(xml_name(n)))
        diag_warning(xml_loc(x, n), "<%s> in <constantsdef> is not known to sphc; ignored",
                     xml_name(n));
    return 0;
}

int xml_constants(XmlCtx *x, const xmlNode *constantsdef)
{
    int bad = 0;
    for (xmlNode *c = xml_first(constantsdef); c; c = xml_next(c))
        bad |= constant(x, c) != 0;
    return bad ? -1 : 0;
}

/* ------------------------------------------------------------------ <parameters> */

static int is_fluid_parameter(const char *key)
{
    static const char *const fluid[] = {
        "Visco", "ViscoBoundFactor", "ViscoTreatment", "DensityDT", "DensityDTvalue",
        "Shifting", "ShiftCoef", "ShiftTFS", "RigidAlgorithm", "FtPause", "FtIgnoreRadius",
        "DtIni", "DtFixed", "DtFixedFile", "DtAllParticles", "PartsOutMax", "RhopOutMin",
        "RhopOutMax", "VerletSteps", "PosDouble", "SavePosDouble", "Boundary", "WrnPartsOut",
        "NstepsBreak", "SvAllSteps", "TimeOutFile", "XPeriodicIncY", "YPeriodicIncX",
        "Precision", "MinFluidStop", NULL};
    for (int i = 0; fluid[i]; i++)
        if (!strcmp(key, fluid[i]))
            return 1;
    return 0;
}

/* StepAlgorithm and Kernel: a choice between two words by number. */
static int choice(XmlCtx *x, const xmlNode *n, const char *key, const char *one,
                  const char *two, const char *name)
{
    double v;
    if (xml_number(x, n, "value", 1, &v) != 1)
        return -1;
    if (v != 1 && v != 2) {
        diag_error(xml_loc(x, n), "<parameter key=\"%s\">: value must be 1 (%s) or 2 (%s), "
                                  "got %g", name, one, two, v);
        return -1;
    }
    xml_scene_word(x, xml_loc(x, n), key, v == 1 ? one : two);
    return 0;
}

static int time_value(XmlCtx *x, const xmlNode *n, const char *key, double *v)
{
    if (xml_number(x, n, "value", 1, v) != 1)
        return -1;
    if (!(*v > 0)) {
        diag_error(xml_loc(x, n), "<parameter key=\"%s\">: value must be positive (got %g)",
                   xml_attr(n, "key"), *v);
        return -1;
    }
    xml_scene_number(x, xml_loc(x, n), key, *v);
    return 0;
}

static int parameter(XmlCtx *x, const xmlNode *n)
{
    static const char *const attrs[] = {"key", "value", NULL};
    if (xml_check_attrs(x, n, attrs))
        return -1;
    char *key = xml_attr(n, "key");
    double v;
    if (!key) {
        diag_error(xml_loc(x, n), "<parameter>: missing attribute 'key'");
        return -1;
    }
    if (!strcmp(key, "StepAlgorithm"))
        return choice(x, n, "integrator", "verlet", "symplectic", "StepAlgorithm");
    if (!strcmp(key, "Kernel"))
        return choice(x, n, "kernel", "cubic", "wendland", "Kernel");
    if (!strcmp(key, "TimeMax")) {
        x->has_end = 1;
        return time_value(x, n, "end", &v);
    }
    if (!strcmp(key, "TimeOut"))
        return time_value(x, n, "output", &v);
    if (!strcmp(key, "CoefDtMin"))
        return time_value(x, n, "dtmin", &v);
    if (!is_fluid_parameter(key))
        diag_warning(xml_loc(x, n), "<parameter key=\"%s\"> is not known to sphc; ignored", key);
    return 0;
}

int xml_parameters(XmlCtx *x, const xmlNode *parameters)
{
    int bad = 0;
    for (xmlNode *c = xml_first(parameters); c; c = xml_next(c)) {
        if (xml_is(c, "parameter"))
            bad |= parameter(x, c) != 0;
        else if (!xml_is(c, "simulationdomain")) {
            diag_error(xml_loc(x, c), "<%s> is not expected in <parameters> (expected "
                                      "<parameter> or <simulationdomain>)", xml_name(c));
            bad = 1;
        }
    }
    if (!bad && !x->has_end) {
        diag_error(xml_loc(x, parameters), "<parameters> needs <parameter key=\"TimeMax\" "
                                           "value=\"...\"/> (the end time)");
        bad = 1;
    }
    return bad ? -1 : 0;
}
