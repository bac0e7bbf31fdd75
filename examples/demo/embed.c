/* embed.c -- build-time helper: writes a text file (the library's GLSL
 * twins in shaders/) as a C string constant, so the demo's shaders use the
 * very file the library's tests check.
 *   demo_embed INPUT OUTPUT NAME */
#include <stdio.h>

int main(int argc, char** argv) {
    if (argc != 4) {
        fprintf(stderr, "usage: demo_embed INPUT OUTPUT NAME\n");
        return 2;
    }
    FILE* in = fopen(argv[1], "rb");
    FILE* out = fopen(argv[2], "wb");
    if (!in || !out) {
        fprintf(stderr, "demo_embed: cannot open %s or %s\n", argv[1], argv[2]);
        return 1;
    }
    fprintf(out, "/* generated from %s by demo_embed; do not edit */\n", argv[1]);
    fprintf(out, "static const char %s[] =\n\"", argv[3]);
    int c, col = 0;
    while ((c = fgetc(in)) != EOF) {
        if (c == '\n') {
            fputs("\\n\"\n\"", out);
            col = 0;
            continue;
        }
        if (c == '\\' || c == '"') fputc('\\', out);
        if (c == '\t') {
            fputs("\\t", out);
            continue;
        }
        if (c == '\r') continue;
        fputc(c, out);
        ++col;
    }
    fputs("\";\n", out);
    fclose(in);
    return fclose(out) == 0 ? 0 : 1;
}
