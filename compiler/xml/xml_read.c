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
#include <iconv.h>
#include <limits.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <libxml/SAX2.h>
#include <libxml/entities.h>
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

/* ------------------------------------------------------------------ the encoding */

/* A case in UTF-16 or UTF-32 (by its byte order mark, or by "<?" written in two or four
 * bytes a character) is converted to UTF-8 before anything reads it: the escaping of '<'
 * above reads ASCII bytes, and the diagnostics show its lines (source.c) in UTF-8.  Other
 * encodings keep ASCII's bytes, and libxml2 reads them by their declaration. */
static const char *wide_encoding(const char *text, size_t len, size_t *bom)
{
    static const struct {
        const char *bytes;
        size_t n, bom;
        const char *name;
    } MARKS[] = {
        {"\xFF\xFE\0\0", 4, 4, "UTF-32LE"}, {"\0\0\xFE\xFF", 4, 4, "UTF-32BE"},
        {"\xFF\xFE", 2, 2, "UTF-16LE"},     {"\xFE\xFF", 2, 2, "UTF-16BE"},
        {"<\0\0\0", 4, 0, "UTF-32LE"},     {"\0\0\0<", 4, 0, "UTF-32BE"},
        {"<\0?\0", 4, 0, "UTF-16LE"},       {"\0<\0?", 4, 0, "UTF-16BE"},
    };
    for (size_t k = 0; k < sizeof MARKS / sizeof MARKS[0]; k++)
        if (len >= MARKS[k].n && !memcmp(text, MARKS[k].bytes, MARKS[k].n)) {
            *bom = MARKS[k].bom;
            return MARKS[k].name;
        }
    return NULL;
}

/* text[0 .. len-1] in encoding enc (after its byte order mark of bom bytes) as UTF-8, in
 * *outlen bytes; NULL after an error naming the line where the conversion stopped. */
static char *to_utf8(const char *path, const char *enc, size_t bom, const char *text,
                     size_t len, size_t *outlen)
{
    iconv_t cd = iconv_open("UTF-8", enc);
    if (cd == (iconv_t)-1) {
        diag_error((SrcLoc){path, 0, 0}, "the file is in %s, which this system cannot convert "
                                         "(save it as UTF-8)", enc);
        return NULL;
    }
    const size_t cap = len + len / 2 + 16; /* 2 bytes of UTF-16 give at most 3 of UTF-8 */
    char *out = ast_alloc(cap), *in = (char *)text + bom, *o = out;
    size_t inleft = len - bom, outleft = cap - 1;
    const int failed = iconv(cd, &in, &inleft, &o, &outleft) == (size_t)-1;
    const int err = errno;
    iconv_close(cd);
    if (failed) {
        int line = 1;
        for (const char *c = out; c < o; c++)
            line += *c == '\n';
        source_set_text(path, out, (size_t)(o - out)); /* the lines converted */
        diag_error((SrcLoc){path, line, 0}, "the file is in %s (by its %s), but its bytes at "
                   "offset %zu are %s %s (save it as UTF-8)", enc,
                   bom ? "byte order mark" : "first characters", (size_t)(in - text),
                   err == EINVAL ? "an incomplete character of" : "not valid", enc);
        free(out);
        return NULL;
    }
    *o = 0;
    *outlen = (size_t)(o - out);
    return out;
}

/* ------------------------------------------------------------------ libxml2 */

/* Entities.  libxml2 keeps a reference (&name;) in the tree and expands it each time the
 * text is read, so a few kilobytes of nested or repeated references could expand to
 * gigabytes.  Each time the parser looks an entity up (where it is declared and where it
 * is used), its text counts against one budget for the file: past ENTITY_TEXT_MAX bytes
 * in all, or past ENTITY_REFS_MAX look-ups (each a node of the tree), the file is
 * refused.  The text counted is an upper bound of what the entity expands to, so the tree
 * read afterwards stays within the budget too.  External entities and parameter entities
 * are refused, not read. */
enum {
    ENTITY_TEXT_MAX = 1 << 20,
    ENTITY_REFS_MAX = 100000,
    ENTITY_DEPTH_MAX = 40, /* entities in entities, as libxml2's own limit */
    NAME_SHOWN = 64        /* bytes of a name a message shows */
};

typedef struct {
    const char *file;
    int reported;
    xmlParserCtxt *ctxt;
    size_t entity_text; /* bytes counted so far */
    long entity_refs;   /* look-ups so far */
} ParseState;

/* The parse in progress, for the entity callbacks. */
static ParseState *parsing;

/* The first error libxml2 finds is reported; the ones that follow from it are not. */
#if LIBXML_VERSION >= 21200
static void xml_error(void *data, const xmlError *err)
#else
static void xml_error(void *data, xmlErrorPtr err)
#endif
{
    ParseState *sink = data;
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

/* A name from the file, cut to NAME_SHOWN bytes. */
static const char *shown(const xmlChar *name, char buf[NAME_SHOWN + 4])
{
    snprintf(buf, NAME_SHOWN + 4, "%.*s%s", NAME_SHOWN, name ? (const char *)name : "",
             name && strlen((const char *)name) > NAME_SHOWN ? "..." : "");
    return buf;
}

/* An entity error, at the line the document's parser has reached; the parse stops. */
static void entity_error(ParseState *p, void *ctx, const char *fmt, ...)
{
    if (!p->reported) {
        char msg[512];
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, sizeof msg, fmt, ap);
        va_end(ap);
        const xmlParserCtxt *c = p->ctxt;
        int line = c->inputNr > 0 && c->inputTab[0] ? c->inputTab[0]->line : 0;
        diag_error((SrcLoc){p->file, line > 0 ? line : 0, 0}, "%s", msg);
        p->reported = 1;
    }
    xmlStopParser(ctx);
}

/* What a general entity counts: its text with each reference in it replaced by what the
 * entity named counts, or by the reference itself when that is more (an upper bound of
 * its expansion and at least its length), capped at ENTITY_TEXT_MAX + 1.  Remembered in
 * the entity's _private (the count + 2; 1 while it is counted) once every entity it
 * names is declared.  -1 after an error. */
#define COUNTING ((void *)1)
static long entity_count(ParseState *p, void *ctx, xmlEntity *ent, int depth, int *partial)
{
    char b1[NAME_SHOWN + 4];
    if (ent->etype == XML_INTERNAL_PREDEFINED_ENTITY)
        return 1;
    if (ent->etype != XML_INTERNAL_GENERAL_ENTITY) {
        char file[200];
        snprintf(file, sizeof file, "%s", ent->SystemID ? (const char *)ent->SystemID : "");
        entity_error(p, ctx, "external entity '&%s;' (file '%s') is not read: external "
                             "entities are refused", shown(ent->name, b1), file);
        return -1;
    }
    if (ent->_private == COUNTING) {
        entity_error(p, ctx, "entity '&%s;' refers to itself", shown(ent->name, b1));
        return -1;
    }
    if (ent->_private)
        return (long)((uintptr_t)ent->_private - 2);
    if (depth > ENTITY_DEPTH_MAX) {
        entity_error(p, ctx, "entities nest more than %d deep (at '&%s;')", ENTITY_DEPTH_MAX,
                     shown(ent->name, b1));
        return -1;
    }
    ent->_private = COUNTING;
    const char *s = ent->content ? (const char *)ent->content : "";
    size_t count = 0;
    int undeclared = 0;
    while (*s && count <= ENTITY_TEXT_MAX) {
        const char *amp = strchr(s, '&'), *semi = amp ? strchr(amp, ';') : NULL;
        if (!semi) {
            count += strlen(s);
            break;
        }
        count += (size_t)(semi + 1 - s);
        s = semi + 1;
        if (amp[1] == '#') /* a character reference (one character, fewer bytes) */
            continue;
        xmlChar *name = xmlStrndup((const xmlChar *)amp + 1, (int)(semi - amp - 1));
        xmlEntity *sub = xmlGetDocEntity(p->ctxt->myDoc, name);
        xmlFree(name);
        if (!sub) {
            undeclared = 1; /* declared later, or an error of libxml2's */
            continue;
        }
        long n = entity_count(p, ctx, sub, depth + 1, &undeclared);
        if (n < 0)
            return -1;
        if ((size_t)n > (size_t)(semi + 1 - amp))
            count += (size_t)n - (size_t)(semi + 1 - amp);
    }
    if (count > ENTITY_TEXT_MAX)
        count = ENTITY_TEXT_MAX + 1;
    ent->_private = undeclared ? NULL : (void *)(uintptr_t)(count + 2);
    *partial |= undeclared;
    return (long)count;
}

/* libxml2 looks a general entity up: it is counted first. */
static xmlEntity *get_entity(void *ctx, const xmlChar *name)
{
    ParseState *p = parsing;
    char b[NAME_SHOWN + 4];
    xmlEntity *ent = p->ctxt->myDoc ? xmlGetDocEntity(p->ctxt->myDoc, name) : NULL;
    if (!p->reported && ent && ent->etype != XML_INTERNAL_PREDEFINED_ENTITY) {
        int partial = 0;
        long n = entity_count(p, ctx, ent, 0, &partial);
        if (n > ENTITY_TEXT_MAX)
            entity_error(p, ctx, "entity '&%s;' expands to more than %d bytes of text (the "
                                 "limit for a case file)", shown(name, b), ENTITY_TEXT_MAX);
        else if (n >= 0 && (p->entity_text += (size_t)n) > ENTITY_TEXT_MAX)
            entity_error(p, ctx, "entities expand to more than %d bytes of text in all (the "
                                 "limit for a case file; '&%s;' adds %ld here)",
                         ENTITY_TEXT_MAX, shown(name, b), n);
        else if (n >= 0 && ++p->entity_refs > ENTITY_REFS_MAX)
            entity_error(p, ctx, "more than %d entity declarations and references (the limit "
                                 "for a case file)", ENTITY_REFS_MAX);
    }
    if (p->reported) {
        xmlStopParser(ctx);
        return NULL;
    }
    return xmlSAX2GetEntity(ctx, name);
}

static xmlEntity *get_parameter_entity(void *ctx, const xmlChar *name)
{
    char b[NAME_SHOWN + 4];
    entity_error(parsing, ctx, "parameter entity '%%%s;': parameter entities are not read",
                 shown(name, b));
    return NULL;
}

/* Line numbers.  libxml2 keeps a node's line in 16 bits: past line 65535 an element's line
 * reads 65535 (XML_PARSE_BIG_LINES keeps the real one for text nodes only, and
 * xmlGetLineNo of an element then reads a neighbouring text node's, often the next line).
 * Each element past that line gets its line in psvi (which only schema validation uses,
 * and sphc does not validate); xml_loc reads it there. */
static void start_element(void *ctx, const xmlChar *name, const xmlChar *prefix,
                          const xmlChar *uri, int nns, const xmlChar **ns, int nattrs,
                          int ndefaulted, const xmlChar **attrs)
{
    xmlSAX2StartElementNs(ctx, name, prefix, uri, nns, ns, nattrs, ndefaulted, attrs);
    const xmlParserCtxt *c = ctx;
    if (c->node && c->input && c->input->line >= XML_NODE_LINE_MAX)
        c->node->psvi = (void *)(intptr_t)c->input->line;
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
    size_t bom;
    const char *wide = wide_encoding(raw, len, &bom);
    if (wide) {
        char *utf8 = to_utf8(path, wide, bom, raw, len, &len);
        free(raw);
        if (!(raw = utf8))
            return NULL;
        source_set_text(path, raw, len);
    }
    char *text = escape_attribute_lt(raw, len, &elen);
    free(raw);
    if (elen > INT_MAX) {
        diag_error((SrcLoc){path, 0, 0}, "the file is too large (%zu bytes)", len);
        free(text);
        return NULL;
    }
    xmlParserCtxt *ctxt = xmlNewParserCtxt();
    if (!ctxt) {
        diag_error((SrcLoc){path, 0, 0}, "out of memory");
        free(text);
        return NULL;
    }
    ctxt->sax->getEntity = get_entity;
    ctxt->sax->getParameterEntity = get_parameter_entity;
    ctxt->sax->startElementNs = start_element;
    ParseState state = {path, 0, ctxt, 0, 0};
    parsing = &state;
    xmlSetStructuredErrorFunc(&state, xml_error);
    /* Not XML_PARSE_HUGE: it would lift libxml2's own limits on entities too. */
    /* A converted file is UTF-8 whatever its declaration says. */
    xmlDoc *doc = xmlCtxtReadMemory(ctxt, text, (int)elen, path, wide ? "UTF-8" : NULL,
                                    XML_PARSE_NONET | XML_PARSE_BIG_LINES |
                                        (wide ? XML_PARSE_IGNORE_ENC : 0));
    xmlSetStructuredErrorFunc(NULL, NULL);
    parsing = NULL;
    xmlFreeParserCtxt(ctxt);
    free(text);
    if (!doc && !state.reported)
        diag_error((SrcLoc){path, 0, 0}, "malformed XML");
    if (doc && state.reported) {
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
