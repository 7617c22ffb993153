#include "simulated_uno.hpp"

#include <avr_adc.h>
#include <avr_ioport.h>
#include <avr_uart.h>
#include <sim_avr.h>
#include <sim_elf.h>
#include <sim_io.h>
#include <sim_irq.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <stdexcept>

// simavr 1.6 has no call that frees what its io modules allocate (their irqs); LeakSanitizer
// would report those as leaks of the test. They are the library's: leave them out.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libsimavr\n";
}

namespace fl::test {
namespace {

constexpr uint32_t kVectorBytes = 4;         // ATmega328P: a jmp per vector
constexpr uint32_t kTimer1CompaVector = 11;  // TIMER1_COMPA_vect
constexpr uint64_t kInterruptResponse = 4;   // cycles from the request to the vector (datasheet)
constexpr uint16_t kRamEnd = 0x08FF;
constexpr uint32_t kSpLow = 0x5D;  // SPL, SPH in data space
constexpr uint32_t kSpHigh = 0x5E;

struct Harness {
  const std::vector<uint16_t>* samples = nullptr;
  avr_t* avr = nullptr;
  avr_irq_t* adc0 = nullptr;
  bool warmed_up = false;
  UnoRun run;
  uint64_t isr_cycles_total = 0;
  // add_sample timing (pin 8)
  bool estimator_busy = false;
  uint64_t estimator_start = 0;
  uint64_t estimator_isr_at_start = 0;
  uint64_t estimator_cycles_sum = 0;
  const std::vector<uint64_t>* geometry_calls = nullptr;
};

void on_adc_trigger(avr_irq_t* /*irq*/, uint32_t /*mux*/, void* param) {
  auto* h = static_cast<Harness*>(param);
  // The firmware's first conversion, in setup(), warms the ADC up and is thrown away.
  if (!h->warmed_up) {
    h->warmed_up = true;
    return;
  }
  const auto& s = *h->samples;
  const uint16_t counts = h->run.conversions < s.size() ? s[h->run.conversions] : s.back();
  ++h->run.conversions;
  // simavr converts floor(mV * 1023 / Vref); the smallest mV that gives `counts`:
  const uint32_t millivolts = (static_cast<uint32_t>(counts) * 5000u + 1022u) / 1023u;
  avr_raise_irq(h->adc0, millivolts);
}

void on_uart(avr_irq_t* /*irq*/, uint32_t value, void* param) {
  static_cast<Harness*>(param)->run.serial.push_back(static_cast<char>(value));
}

void on_pin8(avr_irq_t* /*irq*/, uint32_t value, void* param) {
  auto* h = static_cast<Harness*>(param);
  if (value != 0 && !h->estimator_busy) {
    h->estimator_busy = true;
    h->estimator_start = h->avr->cycle;
    h->estimator_isr_at_start = h->isr_cycles_total;
  } else if (value == 0 && h->estimator_busy) {
    h->estimator_busy = false;
    const uint64_t interrupts = h->isr_cycles_total - h->estimator_isr_at_start;
    const uint64_t cycles = h->avr->cycle - h->estimator_start - interrupts;
    const uint64_t call = h->run.estimator_calls++;
    h->estimator_cycles_sum += cycles;
    if (cycles > h->run.estimator_cycles_max) {
      h->run.estimator_cycles_max = cycles;
      h->run.estimator_max_call = call;
    }
    bool geometry = false;
    for (uint64_t g : *h->geometry_calls) geometry = geometry || g == call;
    if (!geometry && cycles > h->run.estimator_cycles_max_steady)
      h->run.estimator_cycles_max_steady = cycles;
  }
}

void no_sleep(avr_t* /*avr*/, avr_cycle_count_t /*how_long*/) {}

}  // namespace

FunctionRange find_symbol(const std::string& elf_path, const std::string& symbol) {
#ifdef FL_AVR_NM
  const std::string nm = FL_AVR_NM;
#else
  const std::string nm = "avr-nm";
#endif
  const std::string command = nm + " -S --defined-only '" + elf_path + "'";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  FunctionRange out;
  if (!pipe) return out;
  std::array<char, 512> buf{};
  while (fgets(buf.data(), static_cast<int>(buf.size()), pipe.get()) != nullptr) {
    // "address size kind name", or "address kind name" for symbols without a size.
    std::istringstream line(buf.data());
    std::vector<std::string> words;
    for (std::string w; line >> w;) words.push_back(w);
    if (words.size() < 3 || words.back() != symbol) continue;
    out.address = static_cast<uint32_t>(std::stoul(words[0], nullptr, 16));
    if (words.size() == 4) out.size = static_cast<uint32_t>(std::stoul(words[1], nullptr, 16));
  }
  return out;
}

UnoRun run_uno(const std::string& elf_path, const std::vector<uint16_t>& samples,
               uint64_t extra_samples, uint64_t flush_cycles,
               const std::vector<uint64_t>& geometry_calls) {
  if (samples.empty()) throw std::invalid_argument("run_uno: no samples");
  const FunctionRange isr = find_symbol(elf_path, "__vector_11");
  if (isr.size == 0) throw std::runtime_error("run_uno: no __vector_11 in " + elf_path);
  const uint32_t slot = kTimer1CompaVector * kVectorBytes;

  elf_firmware_t firmware{};
  if (elf_read_firmware(elf_path.c_str(), &firmware) != 0)
    throw std::runtime_error("run_uno: cannot read " + elf_path);
  avr_t* avr = avr_make_mcu_by_name("atmega328p");
  if (avr == nullptr) throw std::runtime_error("run_uno: simavr has no atmega328p");
  avr_init(avr);
  avr->frequency = 16000000;
  avr_load_firmware(avr, &firmware);
  avr->frequency = 16000000;
  avr->vcc = 5000;
  avr->avcc = 5000;
  avr->aref = 5000;
  avr->sleep = no_sleep;  // jump over sleep instead of waiting in real time

  Harness h;
  h.samples = &samples;
  h.avr = avr;
  h.geometry_calls = &geometry_calls;
  h.adc0 = avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC0);
  avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_OUT_TRIGGER),
                          on_adc_trigger, &h);
  uint32_t flags = 0;
  avr_ioctl(avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
  flags &= ~(static_cast<uint32_t>(AVR_UART_FLAG_STDIO) | AVR_UART_FLAG_POLL_SLEEP);
  avr_ioctl(avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
  avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT), on_uart,
                          &h);
  avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('B'), IOPORT_IRQ_PIN0),
                          on_pin8, &h);

  auto in_isr = [&](uint32_t pc) {
    return pc == slot || (pc >= isr.address && pc < isr.address + isr.size);
  };
  const uint64_t stop_after = samples.size() + extra_samples;
  uint64_t stop_cycle = 0;
  uint64_t isr_current = 0;
  uint64_t isr_sum = 0;
  uint16_t lowest_sp = kRamEnd;
  for (;;) {
    const int state = avr->state;
    if (state == cpu_Done || state == cpu_Crashed)
      throw std::runtime_error("run_uno: the simulated CPU stopped (state " +
                               std::to_string(state) + ")");
    const uint64_t before = avr->cycle;
    const uint32_t pc = avr->pc;
    avr_run(avr);
    const uint64_t spent = avr->cycle - before;
    if (state == cpu_Sleeping) {
      h.run.sleep_cycles += spent;
    } else if (in_isr(pc)) {
      if (pc == slot) isr_current = kInterruptResponse;
      isr_current += spent;
      h.isr_cycles_total += spent + (pc == slot ? kInterruptResponse : 0);
      if (!in_isr(avr->pc)) {  // reti
        ++h.run.isr_calls;
        isr_sum += isr_current;
        if (isr_current > h.run.isr_cycles_max) h.run.isr_cycles_max = isr_current;
      }
    }
    const uint16_t sp =
        static_cast<uint16_t>(avr->data[kSpLow] | (static_cast<uint16_t>(avr->data[kSpHigh]) << 8));
    if (sp < lowest_sp && sp > 0x100) lowest_sp = sp;
    if (stop_cycle == 0 && h.run.conversions >= stop_after) stop_cycle = avr->cycle + flush_cycles;
    if (stop_cycle != 0 && avr->cycle >= stop_cycle) break;
  }
  h.run.cycles = avr->cycle;
  h.run.stack_bytes_max = kRamEnd - lowest_sp;
  if (h.run.isr_calls > 0)
    h.run.isr_cycles_mean = static_cast<double>(isr_sum) / static_cast<double>(h.run.isr_calls);
  if (h.run.estimator_calls > 0)
    h.run.estimator_cycles_mean =
        static_cast<double>(h.estimator_cycles_sum) / static_cast<double>(h.run.estimator_calls);
  avr_terminate(avr);
  std::free(avr);
  std::free(firmware.flash);
  std::free(firmware.eeprom);
  for (uint32_t i = 0; i < firmware.symbolcount; ++i) std::free(firmware.symbol[i]);
  std::free(firmware.symbol);
  return h.run;
}

}  // namespace fl::test
