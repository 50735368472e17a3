/* xml_read.c — reading a SoliDualSPHysics case file and assembling the Program.
 *
 *   <case>
 *     <casedef> <constantsdef/> <mkconfig/> <geometry/> <motion/> </casedef>
 *     <execution> <special> <mathexpressions/> <deformstrucs/> </special>
 *                 <parameters/> </execution>
 *   </case>
 *
 * SoliDualSPHysics files write expressions such as if(x0<=0.0, ...) inside attribute
 * values, where XML wants &lt;.  Before libxml2 sees the text, a '<' inside a quoted
 * attribute value is escaped (line numbers do not change).  The sections are read in
 * dependency order (geometry, scene, expressions, bodies) and the items are appended in
 * the order a .sph model would have them: imports, scene, lets, bodies. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <libxml/parser.h>

#include "util/diag.h"
#include "xml.h"
#include "xml_internal.h"

int xml_is_case_file(const char *path)
{
    size_t n = strlen(path);
    return n > 4 && strcasecmp(path + n - 4, ".xml") == 0;
}

/* ------------------------------------------------------------------ the text */

static char *read_all(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        diag_fatal_noloc("cannot open '%s': %s", path, strerror(errno));
        return NULL;
    }
    size_t cap = 1 << 16, n = 0, got;
    char *buf = ast_alloc(cap);
    while ((got = fread(buf + n, 1, cap - n, f)) > 0) {
        n += got;
        if (n == cap) {
            char *more = ast_alloc(cap * 2);
            memcpy(more, buf, n);
            free(buf);
            buf = more;
            cap *= 2;
        }
    }
    int failed = ferror(f);
    fclose(f);
    if (failed) {
        diag_fatal_noloc("cannot read '%s'", path);
        free(buf);
        return NULL;
    }
    *len = n;
    return buf;
}

/* Length of the construct starting at s that ends with end (whole rest when missing). */
static size_t skip_to(const char *s, size_t len, size_t i, const char *end)
{
    size_t m = strlen(end);
    for (; i + m <= len; i++)
        if (memcmp(s + i, end, m) == 0)
            return i + m;
    return len;
}

/* Copies a start or end tag from s[i] (at '<'), escaping '<' inside quoted values. */
static size_t copy_tag(const char *s, size_t len, size_t i, char *out, size_t *o)
{
    char quote = 0;
    out[(*o)++] = s[i++];
    for (; i < len; i++) {
        char c = s[i];
        if (quote && c == '<') {
            memcpy(out + *o, "&lt;", 4);
            *o += 4;
            continue;
        }
        out[(*o)++] = c;
        if (quote && c == quote)
            quote = 0;
        else if (!quote && (c == '"' || c == '\''))
            quote = c;
        else if (!quote && c == '>')
            return i + 1;
    }
    return i;
}

static char *escape_attribute_lt(const char *s, size_t len, size_t *outlen)
{
    char *out = ast_alloc(4 * len + 1);
    size_t i = 0, o = 0;
    while (i < len) {
        size_t j = i;
        if (s[i] != '<') {
            out[o++] = s[i++];
            continue;
        }
        if (!strncmp(s + i, "<!--", 4))
            j = skip_to(s, len, i + 4, "-->");
        else if (!strncmp(s + i, "<![CDATA[", 9))
            j = skip_to(s, len, i + 9, "]]>");
        else if (!strncmp(s + i, "<?", 2))
            j = skip_to(s, len, i + 2, "?>");
        else if (!strncmp(s + i, "<!", 2))
            j = skip_to(s, len, i + 2, ">");
        else {
            i = copy_tag(s, len, i, out, &o);
            continue;
        }
        memcpy(out + o, s + i, j - i);
        o += j - i;
        i = j;
    }
    out[o] = 0;
    *outlen = o;
    return out;
}

/* ------------------------------------------------------------------ libxml2 */

typedef struct {
    const char *file;
    int reported;
} ErrorSink;

/* The first error libxml2 finds is reported; the ones that follow from it are not. */
#if LIBXML_VERSION >= 21200
static void xml_error(void *data, const xmlError *err)
#else
static void xml_error(void *data, xmlErrorPtr err)
#endif
{
    ErrorSink *sink = data;
    if (!err || err->level < XML_ERR_ERROR || sink->reported)
        return;
    sink->reported = 1;
    char msg[512];
    snprintf(msg, sizeof msg, "%s", err->message ? err->message : "malformed XML");
    size_t n = strlen(msg);
    while (n && (msg[n - 1] == '\n' || msg[n - 1] == ' '))
        msg[--n] = 0;
    SrcLoc loc = {sink->file, err->line > 0 ? err->line : 0, 0};
    diag_error(loc, "malformed XML: %s", msg);
}

static xmlDoc *parse_document(const char *path)
{
    size_t len, elen;
    char *raw = read_all(path, &len);
    if (!raw)
        return NULL;
    if (len == 0) {
        diag_error((SrcLoc){path, 0, 0}, "the file is empty (expected a <case>)");
        free(raw);
        return NULL;
    }
    char *text = escape_attribute_lt(raw, len, &elen);
    free(raw);
    ErrorSink sink = {path, 0};
    xmlSetStructuredErrorFunc(&sink, xml_error);
    xmlDoc *doc = xmlReadMemory(text, (int)elen, path, NULL,
                                XML_PARSE_NONET | XML_PARSE_HUGE);
    xmlSetStructuredErrorFunc(NULL, NULL);
    free(text);
    if (!doc && !sink.reported)
        diag_error((SrcLoc){path, 0, 0}, "malformed XML");
    if (doc && sink.reported) {
        xmlFreeDoc(doc);
        doc = NULL;
    }
    return doc;
}

/* ------------------------------------------------------------------ the case */

/* Required child: reports its absence. */
static xmlNode *need_child(const XmlCtx *x, const xmlNode *n, const char *name)
{
    xmlNode *c = xml_child(n, name);
    if (!c)
        diag_error(xml_loc(x, n), "<%s> needs a <%s> section", xml_name(n), name);
    return c;
}

/* <motion>: accepted (its <objreal> objects are the bodies that <deformstrucs> deforms).  A
 * motion other than a null one would move a rigid object in DualSPHysics; sphc's bodies move
 * only by their dynamics and boundary conditions, so it is ignored with a warning. */
static void read_motion(const XmlCtx *x, const xmlNode *motion)
{
    for (const xmlNode *o = motion->children; o; o = o->next) {
        if (o->type != XML_ELEMENT_NODE || !xml_is(o, "objreal"))
            continue;
        for (const xmlNode *m = o->children; m; m = m->next)
            if (m->type == XML_ELEMENT_NODE && !xml_is(m, "begin") && !xml_is(m, "mvnull") &&
                !xml_is(m, "mnull") && !xml_is(m, "wait"))
                diag_warning(xml_loc(x, m), "<%s> is ignored: the bodies of <deformstrucs> move "
                                            "by their own dynamics (give a velocity with <bcvel>)",
                             xml_name(m));
    }
}

static int read_casedef(XmlCtx *x, const xmlNode *casedef)
{
    static const char *const known[] = {"constantsdef", "mkconfig", "geometry", "motion", NULL};
    int bad = xml_check_children(x, casedef, known) != 0;
    const xmlNode *geometry = need_child(x, casedef, "geometry");
    if (!geometry)
        return -1;
    bad |= xml_geometry(x, geometry) != 0;
    const xmlNode *motion = xml_child(casedef, "motion");
    if (motion)
        read_motion(x, motion);
    const xmlNode *constants = xml_child(casedef, "constantsdef");
    if (constants)
        bad |= xml_constants(x, constants) != 0;
    return bad ? -1 : 0;
}

static int read_special(XmlCtx *x, const xmlNode *special)
{
    static const char *const known[] = {"mathexpressions", "deformstrucs", NULL};
    int bad = xml_check_children(x, special, known) != 0;
    const xmlNode *math = xml_child(special, "mathexpressions");
    if (math)
        bad |= xml_mathexpressions(x, math) != 0;
    const xmlNode *deform = need_child(x, special, "deformstrucs");
    if (deform && !bad)
        bad |= xml_deformstrucs(x, deform) != 0;
    return bad || !deform ? -1 : 0;
}

static int read_execution(XmlCtx *x, const xmlNode *execution)
{
    static const char *const known[] = {"special", "parameters", NULL};
    int bad = xml_check_children(x, execution, known) != 0;
    const xmlNode *parameters = need_child(x, execution, "parameters");
    if (parameters)
        bad |= xml_parameters(x, parameters) != 0;
    const xmlNode *special = need_child(x, execution, "special");
    if (special && !bad)
        bad |= read_special(x, special) != 0;
    return bad || !parameters || !special ? -1 : 0;
}

static int read_case(XmlCtx *x, const xmlNode *root)
{
    static const char *const known[] = {"casedef", "execution", NULL};
    if (!xml_is(root, "case")) {
        diag_error(xml_loc(x, root), "<%s>: a SoliDualSPHysics case file starts with <case>",
                   xml_name(root));
        return -1;
    }
    int bad = xml_check_children(x, root, known) != 0;
    const xmlNode *casedef = need_child(x, root, "casedef");
    const xmlNode *execution = need_child(x, root, "execution");
    if (!casedef || !execution || bad)
        return -1;
    if (read_casedef(x, casedef))
        return -1;
    return read_execution(x, execution);
}

/* ------------------------------------------------------------------ the Program */

static void push_imports(const XmlCtx *x, Program *prog)
{
    for (int k = 1; k <= XML_NLAWS; k++)
        if (x->uses_law[k]) {
            Item it = {0};
            it.kind = IT_IMPORT;
            it.loc = x->law_loc[k];
            it.name = ast_strdup(xml_law(k)->law);
            ast_push_item(prog, it);
        }
}

static void assemble(XmlCtx *x, Program *prog)
{
    push_imports(x, prog);
    Item scene = {0};
    scene.kind = IT_SCENE;
    scene.loc = x->scene_loc;
    scene.scene = xml_scene_settings(x);
    ast_push_item(prog, scene);
    for (int i = 0; i < x->nlets; i++)
        ast_push_item(prog, x->lets[i]);
    Item *fns;
    int nfns;
    xml_factor_functions(x, &fns, &nfns);
    for (int i = 0; i < nfns; i++)
        ast_push_item(prog, fns[i]);
    free(fns);
    for (int i = 0; i < x->nbodies; i++)
        ast_push_item(prog, x->bodies[i]);
}

int xml_import(const char *path, const XmlOptions *opt, Program *prog)
{
    int before = diag_error_count();
    char *file = ast_strdup(path);
    if (!prog->file)
        prog->file = file;
    xmlDoc *doc = parse_document(file);
    if (!doc)
        return diag_error_count() - before;
    XmlCtx x = {0};
    x.file = file;
    if (opt)
        x.opt = *opt;
    const xmlNode *root = xmlDocGetRootElement(doc);
    x.scene_loc = xml_loc(&x, root);
    prog->from_xml = 1;
    if (read_case(&x, root) == 0 && diag_error_count() == before) {
        assemble(&x, prog);
        for (const xmlNode *c = doc->children; c; c = c->next) /* around <case> */
            xml_add_comment(c, &prog->comment);
        for (const xmlNode *c = root->children; c; c = c->next) /* and directly inside it */
            xml_add_comment(c, &prog->comment);
    }
    xmlFreeDoc(doc);
    int errors = diag_error_count() - before;
    if (errors == 0 && prog->n == 0) {
        diag_error((SrcLoc){file, 0, 0}, "nothing was imported");
        errors = 1;
    }
    return errors;
}
