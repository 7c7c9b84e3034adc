// device/protocol/message_table.h: the one list of protocol messages (type code, wire name,
// payload struct) from which the MessageType enum, its names, the encoders, the decoders and the
// dump's dispatch are generated.
//
// X(enumerator, code, wire_name, Payload). Codes below 0x80 travel host -> printer, from 0x80 on
// printer -> host. Each Payload struct is declared in messages.h; its wire layout is written once,
// as the field list messages.cpp walks for both encoding and decoding; describe.cpp renders it.
// docs/protocol.md's message table is checked against this list (tests/device/protocol).
#pragma once

// clang-format off
#define TP_PROTOCOL_MESSAGES(X)                                                                    \
  X(kHello,       0x01, hello,        HelloMsg)       /* host opens the link; resets sequence */  \
  X(kStatusQuery, 0x02, status_query, StatusQueryMsg) /* host asks for a status report now */     \
  X(kReportQuery, 0x03, report_query, ReportQueryMsg) /* host asks for the last job report */     \
  X(kJobBegin,    0x10, job_begin,    JobBeginMsg)    /* start (or resume) a job */               \
  X(kJobEnd,      0x11, job_end,      JobEndMsg)      /* no more swaths: print, feed out, report */ \
  X(kSwathHeader, 0x12, swath_header, SwathHeaderMsg) /* a swath's geometry, size and CRC */      \
  X(kSwathData,   0x13, swath_data,   SwathDataMsg)   /* one chunk of a swath's data */           \
  X(kFeed,        0x14, feed,         FeedMsg)        /* advance the fabric without printing */   \
  X(kCutterCue,   0x15, cutter_cue,   CutterCueMsg)   /* register a cutter cue or notch mark */   \
  X(kCueDone,     0x16, cue_done,     CueDoneMsg)     /* the host fired a cue: feed on */         \
  X(kPause,       0x17, pause,        PauseMsg)                                                   \
  X(kResume,      0x18, resume,       ResumeMsg)                                                  \
  X(kAbort,       0x19, abort,        AbortMsg)                                                   \
  X(kIdentify,    0x81, identify,     IdentifyMsg)    /* answer to hello: model, capabilities */  \
  X(kStatus,      0x82, status,       StatusMsg)      /* acks, credits, state, fabric position */ \
  X(kReject,      0x83, reject,       RejectMsg)      /* a refused host request, with a reason */ \
  X(kJobReport,   0x84, job_report,   JobReportMsg)   /* counters of a finished job */
// clang-format on
