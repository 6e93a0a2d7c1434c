/* The camera helper process: libcamera 0.0.3, serving the kiosk over the
 * socket described in src/camera/camera_proto.h (why a process: src/camera/camera.h).
 *
 * Its main thread waits in poll() on the socket, an eventfd from
 * libcamera's thread and udev's monitor; it finds the camera, opens and
 * configures it, passes the buffers' dmabufs to the kiosk once, and
 * queues a request again whenever the kiosk hands its buffer back.
 * libcamera's thread only sends a FRAME message per completed request.
 *
 * libcamera runs only while a camera is there: without one, udev says
 * when a media device appears and a new CameraManager looks then (0.0.3's
 * udev enumerator keeps pointers to freed entries once a device goes, so
 * a manager is never reused across a device coming back). A camera that
 * libcamera reports removed ends this process; the kiosk starts another. */
#include "camera/camera.h"
#include "util/clock.h"
#include "camera/camera_proto.h"
#include "util/log.h"

#include <libcamera/libcamera.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <memory>
#include <mutex>
#include <streambuf>
#include <string>
#include <vector>

#include <errno.h>
#include <libudev.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/eventfd.h>
#include <time.h>
#include <unistd.h>

using namespace libcamera;

namespace
{

/* Without a camera, look again this often even if udev says nothing. */
constexpr uint64_t REPROBE_NS = 30000000000ull;
/* A media device appeared: look once udev has settled its video nodes
 * (libcamera 0.0.3 lists only devices udev has initialised). */
constexpr uint64_t SETTLE_NS = 1000000000ull;

/* libcamera writes "[time] [pid] LEVEL Category file:line text" lines to
 * stderr by default, which would interleave with ours in the journal.
 * This takes them instead, one priority lower than libcamera gives them.
 * It is written from several threads. */
class LogBridge : public std::streambuf
{
      protected:
	std::streamsize xsputn(const char *s, std::streamsize n) override
	{
		std::lock_guard<std::mutex> lock(mu_);

		line_.append(s, (size_t)n);
		flush_lines();
		return n;
	}
	int overflow(int ch) override
	{
		std::lock_guard<std::mutex> lock(mu_);

		if (ch != EOF)
			line_.push_back((char)ch);
		flush_lines();
		return ch == EOF ? 0 : ch;
	}

      private:
	void flush_lines()
	{
		size_t nl;

		while ((nl = line_.find('\n')) != std::string::npos) {
			forward(line_.substr(0, nl));
			line_.erase(0, nl + 1);
		}
	}
	static void forward(const std::string &line)
	{
		/* Drop the "[time] [pid] " prefix: the journal has both. */
		size_t at = line.find("] [");
		std::string text = line.substr(
		    at == std::string::npos ? 0
					    : std::min(line.size(), line.find("] ", at + 2) + 2));

		/* One step down: what the kiosk does about it is said by
		 * our own lines (libcamera warns of missing sensor tuning
		 * data on every start, for instance). */
		text.erase(0, text.find_first_not_of(' '));
		bool aside = false;
#if LIBCAMERA_VERSION_MAJOR > 0 || LIBCAMERA_VERSION_MINOR >= 3
		/* 0.3 and later look for a dma-buf heap on every start, for
		 * the software ISP, and say ERROR where there is none (a
		 * container, a VM); the kiosk's buffers never come from it. */
		aside = text.find("DmaBufAllocator") != std::string::npos;
#endif
		if (aside)
			log_debug("libcamera: %s", text.c_str());
		else if (text.rfind("ERROR", 0) == 0 || text.rfind("FATAL", 0) == 0)
			log_warn("libcamera: %s", text.c_str());
		else if (text.rfind("WARN", 0) == 0)
			log_info("libcamera: %s", text.c_str());
		else
			log_debug("libcamera: %s", text.c_str());
	}
	std::mutex mu_;
	std::string line_;
};

const char *format_name(const PixelFormat &f, std::string &buf)
{
	buf = f.toString();
	return buf.c_str();
}

void poke(int fd)
{
	uint64_t one = 1;

	if (write(fd, &one, sizeof(one)) < 0 && errno != EAGAIN)
		log_warn("camera: cannot wake the helper: %s", strerror(errno));
}

class Helper
{
      public:
	Helper(int sock) : sock_(sock)
	{
	}
	int run();

      private:
	int setup();
	void read_socket();
	void on_request(Request *r);
	void on_removed(std::shared_ptr<Camera> c);
	void watch_udev();
	void sleep(uint64_t deadline);
	void probe(uint64_t now);
	void drop_manager();
	std::shared_ptr<Camera> find_camera();
	int open();
	int configure_stream(Stream **stream);
	int send_session(Stream *stream);
	void close();
	void requeue(int i);
	void send_present(const std::string &name);

	int sock_;
	int wake_ = -1;
	bool quit_ = false;
	std::string want_id_;
	Size size_;
	bool want_ = false;
	LogBridge log_buf_;
	std::ostream log_stream_{&log_buf_};
	struct udev *udev_ = nullptr;
	struct udev_monitor *monitor_ = nullptr;
	uint64_t probe_at_ = 0;
	bool said_absent_ = false;

	std::unique_ptr<CameraManager> cm_;
	std::string found_id_;
	std::shared_ptr<Camera> cam_;
	std::unique_ptr<CameraConfiguration> config_;
	std::unique_ptr<FrameBufferAllocator> alloc_;
	std::vector<std::unique_ptr<Request>> requests_;
	/* Read by libcamera's thread. */
	std::atomic<bool> streaming_{false};
	std::atomic<uint32_t> generation_{0};
	std::atomic<bool> removed_{false};
	/* Frames the kiosk could not be told of: queued again by run(). */
	std::mutex mu_;
	std::vector<int> unsent_;
};

/* libcamera's thread. A frame the socket cannot take (the kiosk is busy)
 * is dropped: its request goes back from the main thread. */
void Helper::on_request(Request *r)
{
	struct camera_msg m = {};

	if (r->status() == Request::RequestCancelled || !streaming_)
		return;
	const FrameBuffer *fb = r->buffers().begin()->second;

	m.type = CAMERA_MSG_FRAME;
	m.u.frame.generation = generation_;
	m.u.frame.buffer = (int32_t)r->cookie();
	m.u.frame.sequence = fb->metadata().sequence;
	m.u.frame.completed_ns = monotonic_ns();
	if (fb->metadata().status == FrameMetadata::FrameSuccess &&
	    camera_msg_send(sock_, &m, nullptr, 0) == 0)
		return;
	std::lock_guard<std::mutex> lock(mu_);
	unsent_.push_back((int)r->cookie());
	poke(wake_);
}

void Helper::on_removed(std::shared_ptr<Camera> c)
{
	if (c->id() == found_id_) {
		removed_ = true;
		poke(wake_);
	}
}

void Helper::watch_udev()
{
	bool udevd = access("/run/udev/control", F_OK) == 0;

	udev_ = udev_new();
	monitor_ =
	    udev_ ? udev_monitor_new_from_netlink(udev_, udevd ? "udev" : "kernel") : nullptr;
	if (monitor_ &&
	    (udev_monitor_filter_add_match_subsystem_devtype(monitor_, "media", nullptr) ||
	     udev_monitor_filter_add_match_subsystem_devtype(monitor_, "video4linux", nullptr) ||
	     udev_monitor_enable_receiving(monitor_))) {
		udev_monitor_unref(monitor_);
		monitor_ = nullptr;
	}
	if (!monitor_)
		log_debug("camera: cannot watch udev; looking for a camera every %d s",
			  (int)(REPROBE_NS / 1000000000ull));
}

void Helper::sleep(uint64_t deadline)
{
	struct pollfd fds[3] = {{sock_, POLLIN, 0},
				{wake_, POLLIN, 0},
				{monitor_ ? udev_monitor_get_fd(monitor_) : -1, POLLIN, 0}};
	uint64_t now = monotonic_ns(), n;
	int ms = deadline == UINT64_MAX ? -1
		 : deadline <= now
		     ? 0
		     : (int)std::min<uint64_t>((deadline - now + 999999) / 1000000, 3600000);

	if (poll(fds, 3, ms) < 0 && errno != EINTR)
		log_debug("camera: poll: %s", strerror(errno));
	while (read(wake_, &n, sizeof(n)) == sizeof(n))
		;
	if (fds[0].revents)
		read_socket();
	if (!(fds[2].revents & POLLIN))
		return;
	while (struct udev_device *dev = udev_monitor_receive_device(monitor_)) {
		const char *action = udev_device_get_action(dev);

		if (!cm_ && action && !strcmp(action, "add"))
			probe_at_ = std::min(probe_at_, monotonic_ns() + SETTLE_NS);
		udev_device_unref(dev);
	}
}

void Helper::read_socket()
{
	struct camera_msg m;
	int fds[CAMERA_MAX_PLANES], nfds, ret;

	while ((ret = camera_msg_recv(sock_, &m, fds, &nfds)) != -EAGAIN) {
		for (int i = 0; i < nfds; i++)
			::close(fds[i]);
		if (ret == -EPIPE || (ret && ret != -EPROTO)) {
			quit_ = true; /* the kiosk closed the socket or died */
			return;
		}
		if (ret)
			continue;
		if (m.type == CAMERA_MSG_WANT)
			want_ = m.u.want.on != 0;
		else if (m.type == CAMERA_MSG_RELEASE && m.u.release.generation == generation_ &&
			 streaming_ && m.u.release.buffer >= 0 &&
			 (size_t)m.u.release.buffer < requests_.size())
			requeue(m.u.release.buffer);
	}
}

void Helper::requeue(int i)
{
	Request *r = requests_[(size_t)i].get();

	r->reuse(Request::ReuseBuffers);
	if (cam_->queueRequest(r) < 0)
		log_debug("camera: a request could not be queued again");
}

void Helper::send_present(const std::string &name)
{
	struct camera_msg m = {};

	m.type = CAMERA_MSG_PRESENT;
	snprintf(m.u.present.name, sizeof(m.u.present.name), "%s", name.c_str());
	camera_msg_send(sock_, &m, nullptr, 0);
}

/* By id, by index, or the first. */
std::shared_ptr<Camera> Helper::find_camera()
{
	std::vector<std::shared_ptr<Camera>> all = cm_->cameras();
	char *end = nullptr;
	unsigned long index = 0;

	if (!want_id_.empty()) {
		index = strtoul(want_id_.c_str(), &end, 10);
		if (!end || *end)
			return cm_->get(want_id_);
	}
	return index < all.size() ? all[index] : nullptr;
}

void Helper::drop_manager()
{
	if (!cm_)
		return;
	cm_->stop();
	cm_.reset();
	found_id_.clear();
}

/* A new libcamera: kept when it finds the camera, else stopped until the
 * next look. */
void Helper::probe(uint64_t now)
{
	std::shared_ptr<Camera> found;
	int ret;

	probe_at_ = now + REPROBE_NS;
	cm_ = std::make_unique<CameraManager>();
	ret = cm_->start();
	if (ret) {
		log_err("camera: libcamera did not start: %s", strerror(-ret));
		cm_.reset();
		return;
	}
	found = find_camera();
	if (!found) {
		if (!said_absent_)
			log_info("camera: none found%s; showing the image matcaps",
				 want_id_.empty() ? "" : (" with id " + want_id_).c_str());
		said_absent_ = true;
		drop_manager();
		send_present("");
		return;
	}
	found_id_ = found->id();
	cm_->cameraRemoved.connect(this, &Helper::on_removed);
	log_info("camera: %s found", found_id_.c_str());
	send_present(found_id_);
}

int Helper::configure_stream(Stream **stream)
{
	std::string buf;

	config_ = cam_->generateConfiguration({StreamRole::Viewfinder});
	if (!config_ || config_->size() != 1) {
		log_err("camera: %s gives no viewfinder stream", cam_->id().c_str());
		return -EINVAL;
	}
	StreamConfiguration &sc = config_->at(0);
	std::vector<PixelFormat> offered = sc.formats().pixelformats();

	for (const uint32_t *f = camera_formats; *f; f++)
		if (std::find(offered.begin(), offered.end(), PixelFormat(*f)) != offered.end()) {
			sc.pixelFormat = PixelFormat(*f);
			break;
		}
	sc.size = size_;
	if (config_->validate() == CameraConfiguration::Invalid) {
		log_err("camera: %s refuses %s %s", cam_->id().c_str(),
			format_name(sc.pixelFormat, buf), size_.toString().c_str());
		return -EINVAL;
	}
	if (!camera_format_supported(sc.pixelFormat.fourcc())) {
		log_err("camera: %s offers %s, which the kiosk cannot draw (it takes RGB, "
			"NV12, YUV420 or YUYV)",
			cam_->id().c_str(), format_name(sc.pixelFormat, buf));
		return -ENOTSUP;
	}
	int ret = cam_->configure(config_.get());

	if (ret) {
		log_err("camera: %s cannot be configured: %s", cam_->id().c_str(), strerror(-ret));
		return ret;
	}
	*stream = sc.stream();
	return 0;
}

static void fill_colour(const StreamConfiguration &sc, struct camera_msg *m)
{
	const std::optional<ColorSpace> &cs = sc.colorSpace;
	bool known = cs && cs->ycbcrEncoding != ColorSpace::YcbcrEncoding::None;

	m->u.session.encoding = camera_default_encoding((int)sc.size.height);
	m->u.session.range = CAMERA_RANGE_LIMITED;
	m->u.session.colour_space_known = known;
	if (!known)
		return;
	m->u.session.encoding =
	    cs->ycbcrEncoding == ColorSpace::YcbcrEncoding::Rec709    ? CAMERA_ENC_REC709
	    : cs->ycbcrEncoding == ColorSpace::YcbcrEncoding::Rec2020 ? CAMERA_ENC_REC2020
								      : CAMERA_ENC_REC601;
	m->u.session.range =
	    cs->range == ColorSpace::Range::Full ? CAMERA_RANGE_FULL : CAMERA_RANGE_LIMITED;
}

/* The layout, then each buffer's dmabufs (each descriptor once, however
 * many planes it holds) with the planes' offsets. */
int Helper::send_session(Stream *stream)
{
	const StreamConfiguration &sc = config_->at(0);
	const std::vector<std::unique_ptr<FrameBuffer>> &bufs = alloc_->buffers(stream);
	struct camera_msg m = {};
	int ret;

	m.type = CAMERA_MSG_SESSION;
	m.u.session.generation = generation_;
	m.u.session.buffers = (int32_t)bufs.size();
	ret = camera_layout_make(sc.pixelFormat.fourcc(), (int)sc.size.width, (int)sc.size.height,
				 sc.stride, &m.u.session.layout);
	if (ret) {
		log_err("camera: %s gives %s frames with a stride of %u bytes, which cannot be "
			"right",
			cam_->id().c_str(), sc.toString().c_str(), sc.stride);
		return ret;
	}
	fill_colour(sc, &m);
	const struct camera_layout layout = m.u.session.layout;
	if (bufs.size() > CAMERA_MAX_BUFFERS || (ret = camera_msg_send(sock_, &m, nullptr, 0)))
		return ret ? ret : -E2BIG;
	for (size_t b = 0; b < bufs.size(); b++) {
		const std::vector<FrameBuffer::Plane> &planes = bufs[b]->planes();
		int fds[CAMERA_MAX_PLANES], nfds = 0;

		m = {};
		m.type = CAMERA_MSG_BUFFER;
		m.u.buffer.generation = generation_;
		m.u.buffer.buffer = (int32_t)b;
		for (int p = 0; p < layout.planes; p++) {
			/* One dmabuf for every plane, or one each. */
			bool own = (size_t)p < planes.size();
			const FrameBuffer::Plane &fp = planes[own ? (size_t)p : 0];
			int fd = fp.fd.get();

			if (fp.offset == FrameBuffer::Plane::kInvalidOffset)
				return -EINVAL;
			m.u.buffer.offset[p] =
			    own ? fp.offset : planes[0].offset + layout.plane[p].offset;
			m.u.buffer.fd_index[p] = nfds;
			for (int i = 0; i < nfds; i++)
				if (fds[i] == fd)
					m.u.buffer.fd_index[p] = i;
			if (m.u.buffer.fd_index[p] == nfds)
				fds[nfds++] = fd;
		}
		if ((ret = camera_msg_send(sock_, &m, fds, nfds)))
			return ret;
	}
	return 0;
}

int Helper::open()
{
	Stream *stream = nullptr;
	std::string buf;
	int ret;

	cam_ = cm_->get(found_id_);
	if (!cam_)
		return -ENODEV;
	if ((ret = cam_->acquire())) {
		log_err("camera: %s is in use by another program: %s", cam_->id().c_str(),
			strerror(-ret));
		cam_.reset();
		return ret;
	}
	generation_++;
	ret = configure_stream(&stream);
	if (!ret) {
		alloc_ = std::make_unique<FrameBufferAllocator>(cam_);
		ret = alloc_->allocate(stream) < 0 ? -ENOMEM : 0;
	}
	for (size_t b = 0; !ret && b < alloc_->buffers(stream).size(); b++) {
		std::unique_ptr<Request> r = cam_->createRequest(b);

		if (!r || r->addBuffer(stream, alloc_->buffers(stream)[b].get()))
			ret = -ENOMEM;
		requests_.push_back(std::move(r));
	}
	if (!ret)
		ret = send_session(stream);
	if (!ret) {
		cam_->requestCompleted.connect(this, &Helper::on_request);
		ret = cam_->start();
	}
	if (ret) {
		log_err("camera: %s cannot be started (%s); showing the image matcaps",
			found_id_.c_str(), strerror(-ret));
		return ret;
	}
	streaming_ = true;
	for (size_t i = 0; i < requests_.size(); i++)
		requeue((int)i);
	const StreamConfiguration &sc = config_->at(0);
	log_info("camera: %s streams %ux%u %s (stride %u), %zu buffers, colour space %s",
		 found_id_.c_str(), sc.size.width, sc.size.height, format_name(sc.pixelFormat, buf),
		 sc.stride, requests_.size(), ColorSpace::toString(sc.colorSpace).c_str());
	return 0;
}

void Helper::close()
{
	streaming_ = false;
	if (cam_) {
		/* Every queued request comes back cancelled before stop()
		 * returns; none is queued again. */
		cam_->stop();
		cam_->requestCompleted.disconnect(this);
	}
	requests_.clear();
	alloc_.reset();
	config_.reset();
	if (cam_)
		cam_->release();
	cam_.reset();
	std::lock_guard<std::mutex> lock(mu_);
	unsent_.clear();
}

int Helper::setup()
{
	struct camera_msg m;
	struct pollfd pfd = {sock_, POLLIN, 0};
	int fds[CAMERA_MAX_PLANES], nfds;

	/* The kiosk's settings come first. */
	if (poll(&pfd, 1, 10000) != 1 || camera_msg_recv(sock_, &m, fds, &nfds) ||
	    m.type != CAMERA_MSG_CONFIG) {
		log_err("camera: the helper got no settings from the kiosk");
		return -EPROTO;
	}
	m.u.config.id[CAMERA_NAME_MAX - 1] = '\0';
	want_id_ = m.u.config.id;
	size_ = Size((unsigned)m.u.config.width, (unsigned)m.u.config.height);
	log_set_level((enum log_level)m.u.config.log_level);
	wake_ = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
	if (wake_ < 0)
		return -errno;
	/* Before the first libcamera call creates its logger. */
	logSetStream(&log_stream_);
	watch_udev();
	return 0;
}

int Helper::run()
{
	int ret = setup();

	probe_at_ = monotonic_ns();
	while (!ret && !quit_) {
		uint64_t now = monotonic_ns();
		std::vector<int> again;

		if (removed_) {
			/* Stopping a camera libcamera has disconnected is
			 * harmless, but the manager must not see the device
			 * come back: the kiosk starts a new helper. */
			log_warn("camera: %s was removed; back to the image matcaps",
				 found_id_.c_str());
			fflush(stderr);
			_exit(0);
		}
		{
			std::lock_guard<std::mutex> lock(mu_);
			again.swap(unsent_);
		}
		for (int i : again)
			if (streaming_)
				requeue(i);
		if (!cm_ && now >= probe_at_) {
			probe(now);
		} else if (cm_ && want_ && !cam_) {
			if (open()) {
				fflush(stderr);
				_exit(1); /* the kiosk tries again later */
			}
		} else if (cam_ && !want_) {
			close();
		} else {
			sleep(cm_ ? UINT64_MAX : probe_at_);
		}
	}
	close();
	drop_manager();
	if (monitor_)
		udev_monitor_unref(monitor_);
	if (udev_)
		udev_unref(udev_);
	if (wake_ >= 0)
		::close(wake_);
	return ret ? 1 : 0;
}

} /* namespace */

extern "C" int camera_helper_main(int fd)
{
	/* Only the socket and the standard streams: nothing the kiosk holds
	 * (the display, GPIO lines) stays open here. */
	close_range(CAMERA_HELPER_FD + 1, ~0u, 0);
	if (fd != CAMERA_HELPER_FD)
		return 2;
	Helper h(fd);

	return h.run();
}
