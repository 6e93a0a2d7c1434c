/* The build's manual pages and the tables the document checks read, from
 * the settings table (src/config/settings_man.c):
 *   mkman 1|5 VERSION DATE SYSCONFDIR DATADIR   matcap-kiosk(1), kiosk.ini(5)
 *   mkman exit-codes                            the exit statuses, one a line
 *   mkman keys                                  "SECTION KEY", one a line
 *   mkman gltf-features                         what the loader uses and ignores */
#include "config/settings_man.h"
#include "scene/gltf/gltf_features.h"

#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
	struct settings_man_info info;

	if (argc == 2 && !strcmp(argv[1], "exit-codes")) {
		settings_man_exit_table(stdout);
		return 0;
	}
	if (argc == 2 && !strcmp(argv[1], "gltf-features")) {
		gltf_features_print(stdout);
		return 0;
	}
	if (argc == 2 && !strcmp(argv[1], "keys")) {
		settings_man_keys(stdout);
		return 0;
	}
	if (argc != 6 || (strcmp(argv[1], "1") && strcmp(argv[1], "5"))) {
		fprintf(stderr, "usage: mkman 1|5 VERSION DATE SYSCONFDIR DATADIR | exit-codes | "
				"keys | gltf-features\n");
		return 2;
	}
	info = (struct settings_man_info){argv[2], argv[3], argv[4], argv[5]};
	if (argv[1][0] == '1')
		settings_man_page1(stdout, &info);
	else
		settings_man_page5(stdout, &info);
	return fflush(stdout) ? 1 : 0;
}
