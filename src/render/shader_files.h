/* The shader sources built into the binary by shaders/embed.sh. */
#ifndef MK_SHADER_FILES_H
#define MK_SHADER_FILES_H

struct shader_file {
	const char *name;
	const char *text;
};

/* Ends with a {NULL, NULL} entry. */
extern const struct shader_file shader_files[];

#endif
