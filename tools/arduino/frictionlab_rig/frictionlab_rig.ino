// frictionlab_rig: the friction oscillator's Arduino Uno firmware.
//
// Samples the Hall sensor on A0 at a fixed rate from Timer1, feeds every sample to the period
// estimator that frictionlab itself uses (src/estimator/period_estimator.h, included by path,
// never copied), and prints over serial:
//   - a header comment, then "t_us,adc" and one CSV line per raw sample (every FL_RAW_EVERY-th);
//   - one comment line per period (its end, length and whether it was accepted), then one with
//     the running statistics (N, mean T, dT, standard error, mu_k +- d mu_k) and the firmware's
//     health (samples lost, raw lines left out, most samples waiting);
//   - comment lines when the signal is learned, the geometry recognised or the signal lost.
// Comment lines start with '#', so `frictionlab estimate LOG` and spreadsheet tools read the
// capture as a CSV of raw samples.
//
// Build and flash: docs/estimator.md ("Building and flashing a real Uno"). The include path must
// contain the repository's src/ folder (tools/arduino/build-firmware passes it).
//
// Timing: Timer1 (CTC) interrupts every sample period; the interrupt reads the conversion it
// started one period earlier, starts the next one and stores (time, value) in a ring buffer. The
// main loop takes samples from the ring, runs the estimator and prints; it sleeps (idle mode)
// when the ring is empty. Sample times come from counting timer periods exactly (in CPU cycles),
// not from micros(). Digital pin 8 (PB0) is high while the estimator works on a sample, so a
// scope (or the simavr test) can measure it.
#include <Arduino.h>
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

#include "estimator/fixed_format.h"
#include "estimator/period_estimator.h"

// Settings; each can be overridden at build time with -DNAME=value.
#ifndef FL_SAMPLE_HZ
#define FL_SAMPLE_HZ 1000UL  // samples per second (up to 10 kHz)
#endif
#ifndef FL_RAW_EVERY
#define FL_RAW_EVERY 1  // print every n-th raw sample; 0 prints none
#endif
#ifndef FL_BAUD
#define FL_BAUD 250000UL  // exact at 16 MHz; a 1 kHz raw stream needs about 13 kB/s
#endif
#ifndef FL_SPACING_M
#define FL_SPACING_M 0.089f  // roller spacing l [m]
#endif
#ifndef FL_SPACING_ERR_M
#define FL_SPACING_ERR_M 0.002f  // its uncertainty dl [m]
#endif
#ifndef FL_GRAVITY
#define FL_GRAVITY 9.81f  // g [m/s^2]
#endif
#ifndef FL_GEOMETRY
#define FL_GEOMETRY 0  // 0: recognise it, 1: one pulse per period, 2: a pair per period
#endif

namespace {

// Timer1 in CTC mode: the smallest prescaler whose count fits in 16 bits.
const uint32_t kCyclesPerSample = F_CPU / FL_SAMPLE_HZ;
const uint16_t kPrescaler = kCyclesPerSample <= 65536UL          ? 1
                            : kCyclesPerSample / 8UL <= 65536UL  ? 8
                            : kCyclesPerSample / 64UL <= 65536UL ? 64
                                                                 : 256;
const uint8_t kClockSelect = kPrescaler == 1    ? _BV(CS10)
                             : kPrescaler == 8  ? _BV(CS11)
                             : kPrescaler == 64 ? (_BV(CS11) | _BV(CS10))
                                                : _BV(CS12);
const uint16_t kCompare = static_cast<uint16_t>(kCyclesPerSample / kPrescaler - 1);
// The true sample period in CPU cycles, and in whole microseconds plus leftover cycles.
const uint32_t kTickCycles = (static_cast<uint32_t>(kCompare) + 1) * kPrescaler;
const uint8_t kCyclesPerUs = static_cast<uint8_t>(F_CPU / 1000000UL);
const uint32_t kTickWholeUs = kTickCycles / kCyclesPerUs;
const uint8_t kTickExtraCycles = static_cast<uint8_t>(kTickCycles % kCyclesPerUs);
// ADC clock: F_CPU/128 (125 kHz, 104 us per conversion) up to 5 kHz, F_CPU/64 above.
const uint8_t kAdcPrescaler =
    FL_SAMPLE_HZ <= 5000UL ? (_BV(ADPS2) | _BV(ADPS1) | _BV(ADPS0)) : (_BV(ADPS2) | _BV(ADPS1));

// Samples from the interrupt to the main loop.
const uint8_t kRing = 64;  // a power of two
volatile uint32_t ring_time[kRing];
volatile uint16_t ring_value[kRing];
volatile uint8_t ring_head = 0;  // written by the interrupt
volatile uint8_t ring_tail = 0;  // written by the main loop
volatile uint16_t overruns = 0;  // samples lost because the ring was full
bool primed = false;             // interrupt only: a conversion is running
uint32_t clock_us = 0;           // interrupt only: time of the conversion it reads next
uint8_t clock_cycles = 0;        // interrupt only: cycles beyond clock_us

fl_estimator::Config make_config() {
  fl_estimator::Config c;
  c.spacing_m = FL_SPACING_M;
  c.spacing_err_m = FL_SPACING_ERR_M;
  c.gravity_m_s2 = FL_GRAVITY;
  c.geometry = static_cast<fl_estimator::Geometry>(FL_GEOMETRY);
  return c;
}

fl_estimator::PeriodEstimator estimator(make_config());
uint32_t periods_printed = 0;
uint16_t raw_countdown = 1;
uint16_t raw_dropped = 0;  // raw lines left out because the serial buffer was full
uint8_t backlog_max = 0;   // most samples ever waiting in the ring

// Output goes straight into Serial's transmit buffer (256 bytes with build-firmware's flags; the
// UART interrupt empties it); text constants stay in flash (F()): the Uno has 2 KiB of RAM.
void put(const __FlashStringHelper* text) {
  Serial.print(text);
}

void put_uint(uint32_t v) {
  char buf[12];
  Serial.write(reinterpret_cast<const uint8_t*>(buf), fl_estimator::format_uint(buf, v));
}

void put_fixed(float v, uint8_t decimals) {
  char buf[24];
  Serial.write(reinterpret_cast<const uint8_t*>(buf), fl_estimator::format_fixed(buf, v, decimals));
}

void send_line() {
  Serial.write('\n');
}

void print_header() {
  put(F("# frictionlab rig firmware 1: sample_hz="));
  put_uint(FL_SAMPLE_HZ);
  put(F(" sample_us="));
  put_fixed(static_cast<float>(kTickCycles) / kCyclesPerUs, 4);
  put(F(" raw_every="));
  put_uint(FL_RAW_EVERY);
  put(F(" spacing_m="));
  put_fixed(FL_SPACING_M, 4);
  put(F(" spacing_err_m="));
  put_fixed(FL_SPACING_ERR_M, 4);
  put(F(" gravity="));
  put_fixed(FL_GRAVITY, 3);
  put(F(" geometry="));
  put(FL_GEOMETRY == 1 ? F("one") : FL_GEOMETRY == 2 ? F("pair") : F("auto"));
  send_line();
#if SERIAL_TX_BUFFER_SIZE < 256
  put(F("# note: built with a serial buffer of fewer than 256 bytes: raw lines may be left out"));
  send_line();
#endif
  put(F("t_us,adc"));
  send_line();
}

const __FlashStringHelper* status_name(uint8_t status) {
  return status == fl_estimator::kAccepted          ? F("accepted")
         : status == fl_estimator::kRejectedOutlier ? F("outlier")
                                                    : F("broken");
}

uint8_t backlog() {
  return (ring_head - ring_tail) & (kRing - 1);
}

// Lines wait until they fit in the serial buffer, so that printing never holds up the estimator;
// at most one is written per sample.
uint8_t pending_notes = 0;    // kSignalLearned, kGeometryFound, kRestart not printed yet
uint32_t stats_printed = 0;   // period count of the last statistics line
bool output_waiting = false;  // something may be waiting to be printed
const int kNoteRoom = 80;     // longest note line
const int kPeriodRoom = 72;   // longest period line
const int kStatsRoom = 232;   // longest statistics line

void print_note() {
  if (pending_notes & fl_estimator::kSignalLearned) {
    pending_notes &= ~fl_estimator::kSignalLearned;
    put(F("# signal learned: baseline="));
    put_fixed(estimator.baseline(), 1);
    put(F(" polarity="));
    put(estimator.polarity() > 0 ? F("+1") : F("-1"));
    put(F(" timing_level="));
    put_fixed(estimator.timing_level(), 1);
  } else if (pending_notes & fl_estimator::kGeometryFound) {
    pending_notes &= ~fl_estimator::kGeometryFound;
    put(estimator.geometry() == fl_estimator::kPulsePair
            ? F("# geometry: a pair of pulses per period")
            : F("# geometry: one pulse per period"));
  } else {
    pending_notes = 0;
    put(F("# signal lost: learning it again"));
  }
  send_line();
}

void print_period() {
  const fl_estimator::Period& p = estimator.period(periods_printed);
  put(F("# period i="));
  put_uint(periods_printed);
  put(F(" end_us="));
  put_uint(p.end.us);
  put(F(" T_us="));
  put_fixed(p.period_us, 1);
  put(F(" "));
  put(status_name(p.status));
  send_line();
}

// The running statistics after the first `periods` periods.
void print_stats(uint32_t periods) {
  const fl_estimator::Stats s = estimator.stats();
  put(F("# stats periods="));
  put_uint(periods);
  put(F(" N="));
  put_uint(s.periods_used);
  put(F(" discarded="));
  put_uint(s.periods_discarded);
  put(F(" T_mean_us="));
  put_fixed(s.period_s * 1e6f, 1);
  put(F(" dT_us="));
  put_fixed(s.period_std_s * 1e6f, 1);
  put(F(" sem_us="));
  put_fixed(s.period_sem_s * 1e6f, 1);
  put(F(" mu_k="));
  put_fixed(s.mu_k, 5);
  put(F(" dmu_worst="));
  put_fixed(s.mu_k_err_worst, 5);
  put(F(" dmu_quad="));
  put_fixed(s.mu_k_err_quadrature, 5);
  put(F(" overruns="));
  put_uint(overruns);
  put(F(" raw_dropped="));
  put_uint(raw_dropped);
  put(F(" backlog_max="));
  put_uint(backlog_max);
  send_line();
}

// Writes the next waiting line if it fits: notes, then periods in order, then the statistics.
// Clears output_waiting once everything is out.
void print_pending() {
  const int room = Serial.availableForWrite();
  if (pending_notes != 0) {
    if (room >= kNoteRoom) print_note();
    return;
  }
  const uint32_t judged = estimator.period_count();
  while (periods_printed < judged && !estimator.has_period(periods_printed)) ++periods_printed;
  if (periods_printed < judged) {
    if (room >= kPeriodRoom) {
      print_period();
      ++periods_printed;
    }
    return;
  }
  if (stats_printed != judged) {
    if (room >= kStatsRoom) {
      print_stats(judged);
      stats_printed = judged;
      output_waiting = false;
    }
    return;
  }
  output_waiting = false;
}

// A raw line waits for room in the serial buffer while the sample ring is less than half full;
// beyond that it is left out (and counted), so that sampling never stops.
void print_raw(uint32_t t, uint16_t value) {
  char text[20];
  uint8_t n = fl_estimator::format_uint(text, t);
  text[n++] = ',';
  n = static_cast<uint8_t>(n + fl_estimator::format_uint(text + n, value));
  text[n++] = '\n';
  while (Serial.availableForWrite() < n) {
    if (backlog() >= kRing / 2) {
      if (raw_dropped != 0xFFFF) ++raw_dropped;
      return;
    }
  }
  Serial.write(reinterpret_cast<const uint8_t*>(text), n);
}

}  // namespace

ISR(TIMER1_COMPA_vect) {
  const uint16_t value = ADC;  // the conversion started one sample period ago
  ADCSRA |= _BV(ADSC);         // sample now, read at the next tick
  if (!primed) {
    primed = true;
    return;
  }
  const uint8_t head = ring_head;
  const uint8_t next = (head + 1) & (kRing - 1);
  if (next != ring_tail) {
    ring_time[head] = clock_us;
    ring_value[head] = value;
    ring_head = next;
  } else if (overruns != 0xFFFF) {
    ++overruns;
  }
  clock_us += kTickWholeUs;
  clock_cycles = static_cast<uint8_t>(clock_cycles + kTickExtraCycles);
  if (clock_cycles >= kCyclesPerUs) {
    clock_cycles = static_cast<uint8_t>(clock_cycles - kCyclesPerUs);
    ++clock_us;
  }
}

void setup() {
  TIMSK0 = 0;         // no millis() interrupt: less jitter, more time for the estimator
  DDRB |= _BV(DDB0);  // pin 8: high while the estimator works on a sample
  PORTB &= ~_BV(PORTB0);
  Serial.begin(FL_BAUD);
  print_header();
  ADMUX = _BV(REFS0);  // AVcc reference, channel A0
  DIDR0 = _BV(ADC0D);  // no digital input buffer on A0
  ADCSRA = _BV(ADEN) | kAdcPrescaler;
  // The first conversion after enabling the ADC takes 25 ADC clocks instead of 13 (100 us at
  // 10 kHz sampling: a whole sample period); do it now, untimed, and throw it away.
  ADCSRA |= _BV(ADSC);
  while (ADCSRA & _BV(ADSC)) {
  }
  TCCR1A = 0;
  TCCR1B = 0;
  TCNT1 = 0;
  OCR1A = kCompare;
  TIFR1 = _BV(OCF1A);
  TIMSK1 = _BV(OCIE1A);
  TCCR1B = _BV(WGM12) | kClockSelect;
  set_sleep_mode(SLEEP_MODE_IDLE);
}

// One sample per pass; loop() itself never returns, which saves the Arduino main loop's
// serialEventRun() check after every sample.
void loop() {
  for (;;) {
    cli();
    const uint8_t tail = ring_tail;
    if (tail == ring_head) {
      sei();
      if (output_waiting) print_pending();
      // Sleep until an interrupt brings a sample or frees serial buffer space (sei takes effect
      // only after sleep has started, so no interrupt slips in between).
      cli();
      if (ring_tail == ring_head) {
        sleep_enable();
        sei();
        sleep_cpu();
        sleep_disable();
      }
      sei();
      continue;
    }
    const uint8_t waiting = (ring_head - tail) & (kRing - 1);
    sei();
    if (waiting > backlog_max) backlog_max = waiting;
    const uint32_t t = ring_time[tail];
    const uint16_t value = ring_value[tail];
    ring_tail = (tail + 1) & (kRing - 1);

    PORTB |= _BV(PORTB0);
    asm volatile("" ::: "memory");
    const uint8_t events = estimator.add_sample(t, value);
    asm volatile("" ::: "memory");
    PORTB &= ~_BV(PORTB0);

    if (FL_RAW_EVERY != 0 && --raw_countdown == 0) {
      raw_countdown = FL_RAW_EVERY;
      print_raw(t, value);
    }
    if (events != 0) {
      pending_notes |= events & (fl_estimator::kSignalLearned | fl_estimator::kGeometryFound |
                                 fl_estimator::kRestart);
      output_waiting = true;
    }
    if (output_waiting) print_pending();
  }
}
