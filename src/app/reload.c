#include "app/reload.h"
#include "util/log.h"

void reload_failed(const char *what)
{
	char cause[768];

	log_last_error(cause, sizeof(cause));
	if (cause[0])
		log_err("reload: %s; keeping the scene on screen (%s)", what, cause);
	else
		log_err("reload: %s; keeping the scene on screen", what);
}

int reload_content(struct content *shown, const struct content_config *cfg, struct renderer *r,
		   int width, int height)
{
	struct content fresh;
	int ret = content_load(&fresh, cfg, true);

	if (!ret && (ret = content_prepare(&fresh, cfg, width, height)))
		content_release(&fresh);
	if (ret) {
		reload_failed("the scene does not load");
		return ret;
	}
	ret = content_upload(&fresh, r);
	if (ret) {
		log_err("reload: the new scene does not fit on the GPU; keeping the one on screen");
		content_release(&fresh);
		if (content_upload(shown, r))
			log_err("reload: the scene on screen could not be restored either");
		return ret;
	}
	content_release(shown);
	*shown = fresh;
	return 0;
}

unsigned reload_reopen(const struct options *started, const struct options *applied,
		       const struct options *fresh)
{
	unsigned since_start = options_changed(started, fresh);
	unsigned since_last = options_changed(applied, fresh);
	unsigned reopen = 0;

	for (int i = 0; i < OPTIONS_SECTIONS; i++) {
		const struct options_section_rule *rule = &options_sections[i];

		/* Warned at every reload until the restart: the kiosk runs on
		 * with what it started with. */
		if (rule->reload == OPTIONS_AT_START && (since_start & 1u << i))
			log_warn("reload: [%s] settings apply %s", rule->name, rule->says);
		if (rule->reload == OPTIONS_REOPEN && (since_last & 1u << i))
			reopen |= 1u << i;
	}
	return reopen;
}
