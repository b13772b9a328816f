/// @file
/// @brief HidDevice over hidapi (hidraw on Linux). Built only with VDFX_WITH_HIDAPI.
#include <hidapi.h>

#include <fstream>
#include <iterator>
#include <mutex>

#include "io/hid_device.h"

namespace vdfx::io {

namespace {

std::string narrow(const wchar_t* w) {
  std::string out;
  if (!w) return out;
  for (; *w; ++w) {
    const auto c = static_cast<std::uint32_t>(*w);
    if (c < 0x80) {
      out.push_back(static_cast<char>(c));
    } else if (c < 0x800) {
      out.push_back(static_cast<char>(0xC0 | (c >> 6)));
      out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
    } else if (c < 0x10000) {
      out.push_back(static_cast<char>(0xE0 | (c >> 12)));
      out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
    } else {
      out.push_back(static_cast<char>(0xF0 | (c >> 18)));
      out.push_back(static_cast<char>(0x80 | ((c >> 12) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
    }
  }
  return out;
}

bool ensure_init() {
  static const bool ok = hid_init() == 0;
  return ok;
}

class HidapiDevice final : public HidDevice {
 public:
  HidapiDevice(hid_device* dev, std::string path) : dev_(dev), path_(std::move(path)) {}
  ~HidapiDevice() override { close(); }

  int read(std::span<std::uint8_t> buffer, int timeout_ms) override {
    if (!dev_) return -1;
    return hid_read_timeout(dev_, buffer.data(), buffer.size(), timeout_ms);
  }
  int write(std::span<const std::uint8_t> data) override {
    if (!dev_) return -1;
    return hid_write(dev_, data.data(), data.size());
  }
  int get_feature(std::span<std::uint8_t> buffer) override {
    if (!dev_) return -1;
    return hid_get_feature_report(dev_, buffer.data(), buffer.size());
  }
  std::vector<std::uint8_t> report_descriptor() override {
#if HID_API_VERSION >= HID_API_MAKE_VERSION(0, 14, 0)
    std::vector<std::uint8_t> buf(HID_API_MAX_REPORT_DESCRIPTOR_SIZE);
    const int n = dev_ ? hid_get_report_descriptor(dev_, buf.data(), buf.size()) : -1;
    buf.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    return buf;
#else
    // hidapi before 0.14 has no call for it; hidraw exposes it in sysfs.
    const auto slash = path_.rfind('/');
    const std::string node = slash == std::string::npos ? path_ : path_.substr(slash + 1);
    std::ifstream in("/sys/class/hidraw/" + node + "/device/report_descriptor", std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
#endif
  }
  std::string last_error() const override {
    return dev_ ? narrow(hid_error(dev_)) : std::string("device closed");
  }
  void close() override {
    if (dev_) hid_close(dev_);
    dev_ = nullptr;
  }

 private:
  hid_device* dev_;
  std::string path_;
};

std::vector<HidDeviceInfo> enumerate_all() {
  std::vector<HidDeviceInfo> out;
  if (!ensure_init()) return out;
  hid_device_info* list = hid_enumerate(0, 0);
  for (hid_device_info* d = list; d; d = d->next) {
    HidDeviceInfo info;
    info.path = d->path ? d->path : "";
    info.vendor_id = d->vendor_id;
    info.product_id = d->product_id;
    info.manufacturer = narrow(d->manufacturer_string);
    info.product = narrow(d->product_string);
    info.serial = narrow(d->serial_number);
    info.usage_page = d->usage_page;
    info.usage = d->usage;
    info.interface_number = d->interface_number;
    out.push_back(std::move(info));
  }
  hid_free_enumeration(list);
  return out;
}

std::unique_ptr<HidDevice> open_path(const std::string& path) {
  if (!ensure_init()) return nullptr;
  hid_device* dev = hid_open_path(path.c_str());
  if (!dev) return nullptr;
  return std::make_unique<HidapiDevice>(dev, path);
}

}  // namespace

bool hid_available() {
  return true;
}

HidSystem default_hid_system() {
  return {enumerate_all, open_path};
}

}  // namespace vdfx::io
