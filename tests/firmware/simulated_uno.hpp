// The rig's firmware on a simulated ATmega328P at 16 MHz (simavr): the ADC's input on A0 comes
// from a list of samples, what the firmware prints on the serial port is collected, and the CPU
// cycles of the sampling interrupt and of the estimator are counted.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fl::test {

// Address range of a function in the firmware, from avr-nm.
struct FunctionRange {
  uint32_t address = 0;  // bytes
  uint32_t size = 0;     // bytes
};

// Looks a symbol up with `avr-nm -S`; address and size 0 when it is not found (size 0 too for a
// symbol without one, such as __heap_start).
FunctionRange find_symbol(const std::string& elf_path, const std::string& symbol);

// What one run measured.
struct UnoRun {
  std::string serial;           // everything the firmware printed
  uint64_t conversions = 0;     // ADC conversions the firmware started
  uint64_t cycles = 0;          // simulated CPU cycles in total
  uint64_t sleep_cycles = 0;    // of which the CPU slept (idle, waiting for a sample)
  uint64_t isr_calls = 0;       // sampling interrupts (TIMER1_COMPA)
  uint64_t isr_cycles_max = 0;  // worst interrupt, from the interrupt response to reti
  double isr_cycles_mean = 0.0;
  uint64_t estimator_calls = 0;       // add_sample calls (pin 8 high)
  uint64_t estimator_cycles_max = 0;  // worst add_sample, interrupts inside it taken out
  uint64_t estimator_max_call = 0;    // which call (0-based) that was
  double estimator_cycles_mean = 0.0;
  // The worst add_sample call apart from the ones that also recognised the geometry (which
  // replays the pulses seen so far, once per run).
  uint64_t estimator_cycles_max_steady = 0;
  uint32_t stack_bytes_max = 0;  // deepest stack seen (RAMEND - lowest SP)
};

// Runs the firmware at `elf_path` with samples[i] as the i-th ADC conversion's input (10-bit
// counts; converted to millivolts on a 5 V reference so the firmware reads exactly samples[i]).
// The run stops `extra_samples` conversions after the last sample (those repeat the last value)
// and then lets `flush_cycles` more cycles pass so the serial output drains.
// `geometry_calls` lists the add_sample call indices to leave out of estimator_cycles_max_steady.
UnoRun run_uno(const std::string& elf_path, const std::vector<uint16_t>& samples,
               uint64_t extra_samples, uint64_t flush_cycles,
               const std::vector<uint64_t>& geometry_calls = {});

}  // namespace fl::test
